#include <ivis/render/landed_extent.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace ivis::render {
namespace {

/// Cells of a coarse probe line: every kCoarseStride-th cell of every kCoarseStride-th line.
constexpr int kCoarseStride = 4;

/// Whether the curved ray of any probed cell of one line lands: every @a stride-th cell (from
/// stride / 2) of column @a index (axis 0) or row @a index (axis 1) of the probe image of @a cells.
bool anyLanded(const RenderScene& scene, const CurvedRayMap& rays, const glm::ivec2& cells, int axis, int index, int stride)
{
    const int length = (cells[1 - axis] - stride / 2 + stride - 1) / stride;
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, length, 8), false,
        [&](const tbb::blocked_range<int>& range, bool landed) {
            if (landed) return true;
            DistanceField::Sampler sampler = scene.distance().sampler();
            std::vector<glm::dvec2> positions;
            for (int k = range.begin(); k != range.end(); ++k) {
                const int along = stride / 2 + k * stride;
                positions.emplace_back((axis == 0 ? index : along) + 0.5, (axis == 0 ? along : index) + 0.5);
            }
            // Their rays traced together: the drawn ones' own rays are traced by the stability rule.
            std::vector<CurvedRayStart> starts(positions.size());
            std::unique_ptr<bool[]> drawn(new bool[positions.size()]);
            rays.startMany(positions.data(), positions.size(), sampler, starts.data(), drawn.get());
            for (std::size_t i = 0; i < positions.size(); ++i)
                if (drawn[i] && rays.landing(starts[i], sampler).region == Region::Indirect) return true;
            return false;
        },
        [](bool a, bool b) { return a || b; });
}

/// The outermost line of @a axis, counted from its first border (or from its last when @a fromEnd),
/// with a landed cell at @a stride: lines from @a first inward in steps of @a step; -1 if none lands.
int outermostLanded(const RenderScene& scene, const CurvedRayMap& rays, const glm::ivec2& cells, int axis, bool fromEnd,
                    int first, int step, int stride)
{
    for (int outer = first; outer < cells[axis]; outer += step)
        if (anyLanded(scene, rays, cells, axis, fromEnd ? cells[axis] - 1 - outer : outer, stride)) return outer;
    return -1;
}

}  // namespace

PictureExtent landedExtent(const RenderScene& scene, const core::Camera& camera, const CurvedRayMethod& method,
                           const PictureExtent& bound)
{
    const glm::dvec2 size = bound.hi - bound.lo;
    if (!(std::isfinite(size.x) && std::isfinite(size.y) && size.x > 0.0 && size.y > 0.0)) return bound;

    // Square cells covering the bound: the probe camera's image is that rectangle (or a little more).
    const double cell = std::max(size.x, size.y) / kLandedExtentProbes;
    const glm::ivec2 cells(std::max(1, int(std::ceil(size.x / cell))), std::max(1, int(std::ceil(size.y / cell))));
    core::Camera probe = camera;
    const double halfHeight = 0.5 * cells.y * cell;
    if (camera.orthographic) probe.orthoHalfHeight = halfHeight;
    else probe.fovYDeg = 2.0 * std::atan(halfHeight) * 180.0 / M_PI;
    probe.windowCentre = 0.5 * (bound.lo + bound.hi);
    const core::CameraFrame frame(probe, cells.x, cells.y);
    const CurvedRayMap rays(scene, frame, method);

    // Per side (columns from the left and the right, rows from the top and the bottom), the
    // outermost line holding a landed cell, swept from the border inward so that the rings inside
    // are never traced: first on a coarse lattice, then cell by cell from one coarse line further
    // out (from the border if the coarse lattice missed every landing); its reach plus one cell.
    const glm::dvec2 corner = probe.windowCentre - 0.5 * glm::dvec2(cells) * cell;  // left, bottom
    PictureExtent landed = PictureExtent::empty();
    for (int axis = 0; axis < 2; ++axis)
        for (bool fromEnd : {false, true}) {
            const int coarse =
                outermostLanded(scene, rays, cells, axis, fromEnd, kCoarseStride / 2, kCoarseStride, kCoarseStride);
            const int outer = outermostLanded(scene, rays, cells, axis, fromEnd, std::max(0, coarse - kCoarseStride), 1, 1);
            if (outer < 0) continue;
            // Columns count from the left, rows from the top: the first border is low on x, high on y.
            const bool high = (axis == 0) == fromEnd;
            const double edge = corner[axis] + (high ? cells[axis] - outer : outer) * cell;
            if (high) landed.hi[axis] = std::min(edge + cell, bound.hi[axis]);
            else landed.lo[axis] = std::max(edge - cell, bound.lo[axis]);
        }
    landed.fixed = bound.fixed;
    return landed.united(offsetMeshExtent(scene.vertices(), camera, 0.0));
}

}  // namespace ivis::render
