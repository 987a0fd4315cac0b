#include <ivis/optimize/sampling_bound.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace ivis::optimize {
namespace {

/// The R2 sequence's steps (Roberts 2018: 1/g and 1/g^2 with g^3 = g + 1): the points
/// (u0 + k a1, v0 + k a2) mod 1 fill the unit square evenly for every prefix.
constexpr double kR2Step[2] = {0.7548776662466927, 0.5698402909980532};

double triangleArea(const core::TriangleMesh& mesh, std::size_t t)
{
    const glm::dvec3 a(mesh.positions[mesh.triangles[t][0]]), b(mesh.positions[mesh.triangles[t][1]]),
        c(mesh.positions[mesh.triangles[t][2]]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

}  // namespace

double evenSamplingBound(const core::TriangleMesh& mesh, const SurfaceVoxels& voxels, std::size_t samples)
{
    if (samples == 0) throw ValueError("the sampling bound needs at least one sample");
    std::vector<double> areas(mesh.triangles.size());
    double total = 0.0;
    for (std::size_t t = 0; t < areas.size(); ++t) total += areas[t] = triangleArea(mesh, t);
    if (!(total > 0.0)) throw ValueError("the sampling bound needs a surface with area");

    std::vector<std::uint64_t> keys;
    keys.reserve(samples);
    double carried = 0.0;  // the fractional shares not yet placed: the counts add up to samples
    for (std::size_t t = 0; t < areas.size(); ++t) {
        const double share = double(samples) * areas[t] / total + carried;
        const std::size_t count = std::size_t(share);
        carried = share - double(count);
        const glm::vec3 a = mesh.positions[mesh.triangles[t][0]], b = mesh.positions[mesh.triangles[t][1]],
                        c = mesh.positions[mesh.triangles[t][2]];
        for (std::size_t k = 0; k < count; ++k) {
            // The unit square folded onto the triangle (u + v > 1 reflected) keeps the spread.
            double u = std::fmod(0.5 + double(k + 1) * kR2Step[0], 1.0);
            double v = std::fmod(0.5 + double(k + 1) * kR2Step[1], 1.0);
            if (u + v > 1.0) {
                u = 1.0 - u;
                v = 1.0 - v;
            }
            keys.push_back(voxels.keyOf(a + float(u) * (b - a) + float(v) * (c - a)));
        }
    }
    return voxels.shareSeen(keys).area;
}

}  // namespace ivis::optimize
