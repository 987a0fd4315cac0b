/// @file view_optimiser.h
/// @brief The interface through which the viewer's "optimise alpha" and "optimise view" buttons
///        call a CPU optimiser in a background thread, and the stand-ins used until the real one
///        (METHOD.md: gradient ascent of alpha, simulated annealing of the view) exists.
/// @note The stand-ins are coarse grid searches of a coarse visibility score; they are NOT the
///       paper's optimisers and say so in their summaries.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <atomic>
#include <functional>
#include <string>

namespace ivis::app {

/// @brief What an optimiser reads and may change: the camera and the method's parameters.
struct ViewState {
    core::Camera camera;
    render::MethodParams method;
};

/// @brief An optimiser's answer.
struct OptimiserResult {
    ViewState state;             ///< the view and parameters to move to
    double energyBefore = 0.0;   ///< score of the view it started from
    double energyAfter = 0.0;    ///< score of the returned view
    int evaluations = 0;         ///< energies computed
    std::string summary;         ///< one line for the panel
};

/// @brief A CPU optimiser: called on a background thread with the scene and the current view;
///        must return promptly once @a cancel becomes true (throwing Cancelled is fine).
/// @warning It must not touch OpenGL; the scene is shared read-only with the UI thread.
using ViewOptimiser =
    std::function<OptimiserResult(const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel)>;

/// @brief Coarse visibility score of a view, a stand-in for METHOD.md's visibility energy: the
///        fraction of the cells of a 32^3 grid over the mesh's bounds holding a mesh vertex in which
///        at least one of @a size x @a size pixel rays (direct or indirect, render::ScreenMap) lands.
/// @throw Cancelled when @a cancel becomes true
double coarseVisibility(const render::RenderScene& scene, const ViewState& view, int size,
                        const std::atomic<bool>* cancel = nullptr);

/// @brief Stand-in for the alpha optimiser: evaluates coarseVisibility (64 x 64 rays) at alpha =
///        0, 0.1, ..., 2 and keeps the best (InverseVis only; other methods are returned unchanged).
ViewOptimiser standInAlphaSearch();

/// @brief Stand-in for the viewpoint optimiser: evaluates coarseVisibility (64 x 64 rays) on the
///        radius-2.5 sphere at theta = 30..150 and phi = 0..330 in 30-degree steps, at the current
///        alpha (no per-view alpha search), and keeps the best.
ViewOptimiser standInViewSearch();

/// @brief What the stand-ins do, for tooltips and docs.
extern const char* const kStandInAlphaDescription;
extern const char* const kStandInViewDescription;

}  // namespace ivis::app
