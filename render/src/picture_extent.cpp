#include <ivis/render/picture_extent.h>

#include <ivis/core/errors.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivis::render {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Largest tangent k of a plane X = k Z through the eye (Z the depth, X the coordinate @a u along
/// one image axis) that touches the ball of radius @a offset around (u, depth): tan(theta + beta)
/// with tan(theta) = u / depth and sin(beta) = offset / r (negative for a ball wholly on the other
/// side); +infinity once theta + beta reaches 90 degrees or the eye is inside the ball.
double tangentReach(double u, double depth, double offset)
{
    const double r2 = u * u + depth * depth, s2 = r2 - offset * offset;
    if (!(s2 > 0.0)) return kInfinity;
    const double s = std::sqrt(s2);
    const double cosine = depth * s - offset * u;  // r^2 cos(theta + beta)
    return cosine > 0.0 ? (u * s + offset * depth) / cosine : kInfinity;
}

}  // namespace

PictureExtent PictureExtent::empty() { return {glm::dvec2(kInfinity), glm::dvec2(-kInfinity), glm::dvec2(0.0)}; }

PictureExtent PictureExtent::united(const PictureExtent& other) const
{
    return {glm::min(lo, other.lo), glm::max(hi, other.hi), glm::max(fixed, other.fixed)};
}

double widestFramedHalfHeight(const core::Camera& camera)
{
    return camera.orthographic ? kMaxFramedOrthoHalfHeight : std::tan(0.5 * kMaxFramedFovYDeg * M_PI / 180.0);
}

PictureExtent offsetMeshExtent(const core::TriangleMesh& mesh, const core::Camera& camera, double offset)
{
    if (!(offset >= 0.0)) throw ValueError("offset " + std::to_string(offset) + " of a picture extent must be >= 0");
    const core::CameraFrame frame(camera, 1, 1);
    const glm::dvec3 eye = camera.eye;
    const auto& positions = mesh.positions;
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, positions.size(), 4096), PictureExtent::empty(),
        [&](const tbb::blocked_range<std::size_t>& range, PictureExtent extent) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                const glm::dvec3 d = glm::dvec3(positions[i]) - eye;
                const glm::dvec2 u(glm::dot(d, frame.right()), glm::dot(d, frame.upVector()));
                if (camera.orthographic) {
                    extent.lo = glm::min(extent.lo, u - offset);
                    extent.hi = glm::max(extent.hi, u + offset);
                    continue;
                }
                const double depth = glm::dot(d, frame.forward());
                for (int axis = 0; axis < 2; ++axis) {
                    extent.hi[axis] = std::max(extent.hi[axis], tangentReach(u[axis], depth, offset));
                    extent.lo[axis] = std::min(extent.lo[axis], -tangentReach(-u[axis], depth, offset));
                }
            }
            return extent;
        },
        [](const PictureExtent& a, const PictureExtent& b) { return a.united(b); });
}

}  // namespace ivis::render
