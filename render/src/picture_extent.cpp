#include <ivis/render/picture_extent.h>

#include <ivis/core/errors.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
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

/// @brief The four sides of a picture: right (+x), up (+y), left (-x), down (-y).
constexpr int kSides = 4;

/// How far the ball of radius @a radius around the point @a d from the eye reaches on @a side of
/// the picture, as a coordinate along that side's outward axis (the negated x or y on the left and
/// at the bottom): the tangent of its tangent plane through the eye (tangentReach), or for an
/// orthographic camera the coordinate plus the radius.
double sideReach(const glm::dvec3& d, const core::CameraFrame& frame, bool orthographic, int side, double radius)
{
    const double u = glm::dot(d, side % 2 == 0 ? frame.right() : frame.upVector());
    const double outward = side < 2 ? u : -u;
    return orthographic ? outward + radius : tangentReach(outward, glm::dot(d, frame.forward()), radius);
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

PictureExtent offsetMeshExtent(const core::ClusteredVertices& vertices, const core::Camera& camera, double offset)
{
    if (!(offset >= 0.0)) throw ValueError("offset " + std::to_string(offset) + " of a picture extent must be >= 0");
    const core::CameraFrame frame(camera, 1, 1);
    const glm::dvec3 eye = camera.eye;
    const auto& positions = vertices.positions();
    const auto& clusters = vertices.clusters();
    // Per side, the farthest reach of any vertex's ball: first each cluster's bound (the reach of
    // its bounding ball grown by the offset, where that ball lies wholly in front of the eye; else
    // unbounded), then the vertices of the cluster with the farthest bound, then those of every
    // cluster whose bound reaches at least as far (in cluster order, a parallel reduction).
    std::vector<std::array<double, kSides>> bounds(clusters.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, clusters.size(), 256), [&](const auto& range) {
        for (std::size_t c = range.begin(); c != range.end(); ++c) {
            const glm::dvec3 d = clusters[c].centre - eye;
            const double radius = clusters[c].radius + offset;
            const bool inFront = camera.orthographic || glm::dot(d, frame.forward()) - radius > 0.0;
            for (int side = 0; side < kSides; ++side)
                bounds[c][side] = inFront ? sideReach(d, frame, camera.orthographic, side, radius) : kInfinity;
        }
    });
    const auto clusterReach = [&](std::size_t c, int side) {
        double reach = -kInfinity;
        for (std::size_t i = clusters[c].begin; i != clusters[c].end; ++i)
            reach = std::max(reach, sideReach(glm::dvec3(positions[i]) - eye, frame, camera.orthographic, side, offset));
        return reach;
    };
    std::array<double, kSides> start;
    start.fill(-kInfinity);
    for (int side = 0; side < kSides && !clusters.empty(); ++side) {
        const auto farthest = std::max_element(bounds.begin(), bounds.end(),
                                               [side](const auto& a, const auto& b) { return a[side] < b[side]; });
        start[side] = clusterReach(std::size_t(farthest - bounds.begin()), side);
    }
    const std::array<double, kSides> reach = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, clusters.size(), 64), start,
        [&](const tbb::blocked_range<std::size_t>& range, std::array<double, kSides> farthest) {
            for (std::size_t c = range.begin(); c != range.end(); ++c)
                for (int side = 0; side < kSides; ++side)
                    if (bounds[c][side] >= start[side]) farthest[side] = std::max(farthest[side], clusterReach(c, side));
            return farthest;
        },
        [](std::array<double, kSides> a, const std::array<double, kSides>& b) {
            for (int side = 0; side < kSides; ++side) a[side] = std::max(a[side], b[side]);
            return a;
        });
    PictureExtent extent;
    extent.hi = glm::dvec2(reach[0], reach[1]);
    extent.lo = -glm::dvec2(reach[2], reach[3]);
    return extent;
}

}  // namespace ivis::render
