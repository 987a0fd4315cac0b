#include <ivis/core/hot_spots.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace ivis::core {
namespace {

/// Unit eigenvectors of the symmetric matrix @a m, ordered by increasing eigenvalue (Jacobi rotations).
std::array<glm::dvec3, 3> principalAxes(glm::dmat3 m)
{
    glm::dmat3 v(1.0);
    for (int sweep = 0; sweep < 50; ++sweep) {
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(m[p][q]) < 1e-15) continue;
                const double theta = 0.5 * std::atan2(2.0 * m[p][q], m[q][q] - m[p][p]);
                const double c = std::cos(theta), s = std::sin(theta);
                glm::dmat3 r(1.0);
                r[p][p] = c;
                r[q][q] = c;
                r[q][p] = s;   // column q, row p
                r[p][q] = -s;  // column p, row q
                m = glm::transpose(r) * m * r;
                v = v * r;
            }
    }
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return m[a][a] < m[b][b]; });
    return {v[order[0]], v[order[1]], v[order[2]]};
}

}  // namespace

HotSpots placeHotSpots(const TriangleMesh& mesh, int count)
{
    if (count < 1 || count > kMaxHotSpots)
        throw ValueError("hot spots: " + std::to_string(count) + " is out of range (1 to " +
                         std::to_string(kMaxHotSpots) + ")");
    if (mesh.positions.empty()) throw ValueError("hot spots need a mesh with vertices");
    glm::dvec3 mean(0.0), lo(1e300), hi(-1e300);
    for (const glm::vec3& p : mesh.positions) {
        mean += glm::dvec3(p);
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    mean /= double(mesh.positions.size());
    glm::dmat3 covariance(0.0);
    for (const glm::vec3& p : mesh.positions) {
        const glm::dvec3 d = glm::dvec3(p) - mean;
        covariance += glm::outerProduct(d, d);
    }
    const std::array<glm::dvec3, 3> axes = principalAxes(covariance);
    HotSpots spots;
    spots.sigma = float(0.06 * glm::length(hi - lo));
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 direction = (k % 2 == 0 ? -1.0 : 1.0) * axes[std::size_t(k / 2)];
        const auto furthest = std::max_element(mesh.positions.begin(), mesh.positions.end(),
                                               [&](const glm::vec3& a, const glm::vec3& b) {
                                                   return glm::dot(glm::dvec3(a), direction) <
                                                          glm::dot(glm::dvec3(b), direction);
                                               });
        spots.centres.push_back(*furthest);
    }
    return spots;
}

std::vector<float> hotSpotValues(const TriangleMesh& mesh, const HotSpots& spots)
{
    std::vector<float> values(mesh.positions.size(), 0.0f);
    const double twoSigmaSquared = 2.0 * double(spots.sigma) * spots.sigma;
    for (std::size_t i = 0; i < values.size(); ++i)
        for (const glm::vec3& centre : spots.centres) {
            const glm::dvec3 d = glm::dvec3(mesh.positions[i]) - glm::dvec3(centre);
            values[i] = std::max(values[i], float(std::exp(-glm::dot(d, d) / twoSigmaSquared)));
        }
    return values;
}

}  // namespace ivis::core
