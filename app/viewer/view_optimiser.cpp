#include "view_optimiser.h"

#include <ivis/core/errors.h>
#include <ivis/render/screen_map.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace ivis::app {
namespace {

constexpr int kCells = 32;
constexpr int kRays = 64;

/// Cell of a point in the kCells^3 grid over @a box, -1 outside.
int cellOf(const glm::vec3& p, const core::Bounds3& box)
{
    int index = 0;
    for (int a = 2; a >= 0; --a) {
        const double extent = std::max(box.hi[a] - box.lo[a], 1e-9);
        const int c = int(std::floor((p[a] - box.lo[a]) / extent * kCells));
        if (c < 0 || c >= kCells) return -1;
        index = index * kCells + c;
    }
    return index;
}

void throwIfCancelled(const std::atomic<bool>* cancel)
{
    if (cancel && *cancel) throw Cancelled("optimisation cancelled");
}

}  // namespace

const char* const kStandInAlphaDescription =
    "STAND-IN (the paper's gradient ascent of alpha is not implemented yet): tries alpha = 0, 0.1, ..., 2 and "
    "keeps the one whose 64x64 rays visit the most cells of a 32^3 grid holding mesh vertices (a coarse "
    "visibility score). InverseVis only.";
const char* const kStandInViewDescription =
    "STAND-IN (the paper's simulated annealing is not implemented yet): tries the views on the radius-2.5 sphere "
    "at theta = 30..150 and phi = 0..330 degrees in 30-degree steps, at the current alpha, and keeps the one "
    "whose 64x64 rays visit the most cells of a 32^3 grid holding mesh vertices.";

double coarseVisibility(const render::RenderScene& scene, const ViewState& view, int size,
                        const std::atomic<bool>* cancel)
{
    const core::Bounds3 box = core::bounds(scene.mesh());
    std::vector<std::uint8_t> marked(std::size_t(kCells) * kCells * kCells, 0);
    for (const glm::vec3& p : scene.mesh().positions)
        if (const int c = cellOf(p, box); c >= 0) marked[std::size_t(c)] = 1;
    const core::CameraFrame frame(view.camera, size, size);
    const render::ScreenMap screen(scene, frame, view.method);
    std::vector<std::atomic<std::uint8_t>> visited(marked.size());
    for (auto& v : visited) v.store(0, std::memory_order_relaxed);
    tbb::parallel_for(tbb::blocked_range<int>(0, size), [&](const tbb::blocked_range<int>& rows) {
        if (cancel && *cancel) return;
        render::DistanceField::Sampler sampler = scene.distance().sampler();
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < size; ++x) {
                const render::PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
                if (m.region == render::Region::Background) continue;
                if (const int c = cellOf(m.point.position, box); c >= 0) visited[std::size_t(c)].store(1, std::memory_order_relaxed);
            }
    });
    throwIfCancelled(cancel);
    std::size_t markedCount = 0, visitedCount = 0;
    for (std::size_t i = 0; i < marked.size(); ++i) {
        markedCount += marked[i];
        visitedCount += marked[i] && visited[i].load(std::memory_order_relaxed);
    }
    return markedCount ? double(visitedCount) / double(markedCount) : 0.0;
}

ViewOptimiser standInAlphaSearch()
{
    return [](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel) {
        OptimiserResult result;
        result.state = start;
        result.energyBefore = result.energyAfter = coarseVisibility(scene, start, kRays, &cancel);
        result.evaluations = 1;
        if (start.method.method != render::Method::InverseVis) {
            result.summary = "alpha search applies to InverseVis only; nothing changed";
            return result;
        }
        for (int i = 0; i <= 20; ++i) {
            ViewState trial = start;
            trial.method.curved.alpha = 0.1f * float(i);
            const double energy = coarseVisibility(scene, trial, kRays, &cancel);
            ++result.evaluations;
            if (energy > result.energyAfter + 1e-12) {
                result.energyAfter = energy;
                result.state = trial;
            }
        }
        char text[256];
        std::snprintf(text, sizeof text, "stand-in alpha search: alpha %.2f -> %.2f, coarse visibility %.1f%% -> %.1f%%",
                      start.method.curved.alpha, result.state.method.curved.alpha, 100.0 * result.energyBefore,
                      100.0 * result.energyAfter);
        result.summary = text;
        return result;
    };
}

ViewOptimiser standInViewSearch()
{
    return [](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel) {
        OptimiserResult result;
        result.state = start;
        result.energyBefore = result.energyAfter = coarseVisibility(scene, start, kRays, &cancel);
        result.evaluations = 1;
        for (int theta = 30; theta <= 150; theta += 30)
            for (int phi = 0; phi < 360; phi += 30) {
                ViewState trial = start;
                trial.camera = core::Camera::fromAngles(theta, phi, core::kCameraDistance, start.camera.fovYDeg);
                trial.camera.orthographic = start.camera.orthographic;
                trial.camera.orthoHalfHeight = start.camera.orthoHalfHeight;
                const double energy = coarseVisibility(scene, trial, kRays, &cancel);
                ++result.evaluations;
                if (energy > result.energyAfter + 1e-12) {
                    result.energyAfter = energy;
                    result.state = trial;
                }
            }
        const glm::dvec2 from = start.camera.angles(), to = result.state.camera.angles();
        char text[256];
        std::snprintf(text, sizeof text,
                      "stand-in view search: theta/phi %.0f/%.0f -> %.0f/%.0f, coarse visibility %.1f%% -> %.1f%%", from.x,
                      from.y, to.x, to.y, 100.0 * result.energyBefore, 100.0 * result.energyAfter);
        result.summary = text;
        return result;
    };
}

}  // namespace ivis::app
