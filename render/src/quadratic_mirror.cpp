#include <ivis/render/quadratic_mirror.h>

#include <ivis/core/ray_box.h>
#include <ivis/render/picture_extent.h>
#include <ivis/vdb/box_lattice.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <limits>

namespace ivis::render {
namespace {

glm::dvec3 toEye(const core::CameraFrame& frame, const glm::dvec3& v)
{
    return {glm::dot(v, frame.right()), glm::dot(v, frame.upVector()), -glm::dot(v, frame.forward())};
}

glm::dvec3 toWorld(const core::CameraFrame& frame, const glm::dvec3& v)
{
    return v.x * frame.right() + v.y * frame.upVector() - v.z * frame.forward();
}

/// Smallest positive root of a t^2 + b t + c = 0 (linear when a vanishes); false if none.
bool smallestPositiveRoot(double a, double b, double c, double& t)
{
    if (std::abs(a) < 1e-12) {
        if (std::abs(b) < 1e-15) return false;
        t = -c / b;
        return t > 0.0;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    t = t0 > 0.0 ? t0 : t1;
    return t > 0.0;
}

/// Image-plane bounds of the centres of the cells of an n x n grid over [lo, hi] that pass @a test.
struct GridHits {
    glm::dvec2 lo{std::numeric_limits<double>::infinity()};
    glm::dvec2 hi{-std::numeric_limits<double>::infinity()};
    bool empty() const { return lo.x > hi.x; }
};

template <typename Test>
GridHits gridHits(const glm::dvec2& lo, const glm::dvec2& hi, int n, const Test& test)
{
    const glm::dvec2 cell = (hi - lo) / double(n);
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, n), GridHits{},
        [&](const tbb::blocked_range<int>& rows, GridHits hits) {
            for (int j = rows.begin(); j != rows.end(); ++j)
                for (int i = 0; i < n; ++i) {
                    const glm::dvec2 point = lo + (glm::dvec2(i, j) + 0.5) * cell;
                    if (!test(point)) continue;
                    hits.lo = glm::min(hits.lo, point);
                    hits.hi = glm::max(hits.hi, point);
                }
            return hits;
        },
        [](const GridHits& a, const GridHits& b) { return GridHits{glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; });
}

}  // namespace

bool intersectMirror(const core::CameraFrame& frame, const core::CameraRay& ray, const MirrorParams& params,
                     MirrorHit& hit)
{
    const auto& w = params.w;
    const core::Camera& camera = frame.camera();
    const double zm = -glm::length(camera.target - camera.eye) - params.distanceBehind;
    const glm::dvec3 o = toEye(frame, ray.origin - camera.eye), r = toEye(frame, ray.direction);
    const double a = -(w[0] * r.x * r.x + w[1] * r.y * r.y + w[2] * r.x * r.y);
    const double b = r.z - (2.0 * w[0] * o.x * r.x + 2.0 * w[1] * o.y * r.y + w[2] * (o.x * r.y + o.y * r.x) +
                            w[3] * r.x + w[4] * r.y);
    const double c = o.z - zm - (w[0] * o.x * o.x + w[1] * o.y * o.y + w[2] * o.x * o.y + w[3] * o.x + w[4] * o.y);
    double t;
    if (!smallestPositiveRoot(a, b, c, t)) return false;
    const glm::dvec3 m = o + t * r;
    const glm::dvec3 normal = glm::normalize(glm::dvec3(-2.0 * w[0] * m.x - w[2] * m.y - w[3],
                                                        -2.0 * w[1] * m.y - w[2] * m.x - w[4], 1.0));
    hit.point = glm::vec3(camera.eye + toWorld(frame, m));
    hit.normal = glm::vec3(toWorld(frame, normal));
    return true;
}

PictureExtent mirrorFootprint(const core::Camera& camera, const MirrorParams& params, const core::TriangleBvh& bvh,
                           const core::Bounds3& meshBounds)
{
    const core::CameraFrame frame(camera, 1, 1);
    const float half = float(vdb::kBoxHalfExtent);
    // A mirror ray that lands starts inside the volume's box (MirrorMap) and meets the mesh's bounds.
    auto mayLand = [&](const glm::dvec2& point, MirrorHit& hit) {
        if (!intersectMirror(frame, frame.rayThrough(point), params, hit)) return false;
        if (glm::any(glm::greaterThan(glm::abs(hit.point), glm::vec3(half)))) return false;
        float tEnter, tExit;
        return core::rayBoxInterval(hit.point, hit.normal, meshBounds, tEnter, tExit);
    };
    const double widest = widestFramedHalfHeight(camera);
    constexpr int kCoarse = 96, kFine = 128;
    const GridHits candidates = gridHits(glm::dvec2(-widest), glm::dvec2(widest), kCoarse, [&](const glm::dvec2& p) {
        MirrorHit hit;
        return mayLand(p, hit);
    });
    if (candidates.empty()) return PictureExtent::empty();
    const double coarseCell = 2.0 * widest / kCoarse;
    const glm::dvec2 lo = glm::max(candidates.lo - coarseCell, glm::dvec2(-widest));
    const glm::dvec2 hi = glm::min(candidates.hi + coarseCell, glm::dvec2(widest));
    const GridHits footprint = gridHits(lo, hi, kFine, [&](const glm::dvec2& p) {
        MirrorHit hit;
        return mayLand(p, hit) && bvh.intersect(hit.point, hit.normal).hit();
    });
    if (footprint.empty()) return PictureExtent::empty();
    const glm::dvec2 fineCell = (hi - lo) / double(kFine);
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    PictureExtent extent;
    for (int axis = 0; axis < 2; ++axis) {
        const double low = footprint.lo[axis] - fineCell[axis], high = footprint.hi[axis] + fineCell[axis];
        extent.lo[axis] = low > -widest ? low : -kInfinity;
        extent.hi[axis] = high < widest ? high : kInfinity;
    }
    return extent;
}

}  // namespace ivis::render
