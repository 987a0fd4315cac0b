/// @file view_optimiser.h
/// @brief How the viewer's "optimise" and "readable rule" buttons call the CPU optimisers in a
///        background thread: a function object from the scene and the current view to new
///        parameters, and the implementations on optimize::optimizeParameters,
///        optimize::annealViewpoint and optimize::loosestReadable.
#pragma once

#include "../optimization_options.h"

#include <ivis/core/camera.h>
#include <ivis/core/colormap.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief What an optimiser reads and may change: the camera and the method's parameters.
struct ViewState {
    core::Camera camera;
    render::MethodPtr method;
};

/// @brief An optimiser's answer.
struct OptimiserResult {
    ViewState state;             ///< the view and parameters to move to
    double energyBefore = 0.0;   ///< energy of the view it started from
    double energyAfter = 0.0;    ///< energy of the returned view
    int evaluations = 0;         ///< energies computed
    double seconds = 0.0;
    std::string summary;         ///< one line for the panel and stdout
    std::vector<ViewState> views;  ///< "optimise view" with OptimiserSettings::views > 1: the view set, the best first
};

/// @brief A CPU optimiser, called on a background thread with the scene and the current view.
///        @a cancel is set when the window closes; the optimiser then stops at its next line search
///        or proposal (throwing Cancelled).
/// @warning It must not touch OpenGL; the scene is shared read-only with the UI thread.
using ViewOptimiser =
    std::function<OptimiserResult(const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel)>;

/// @brief Settings of both optimisers (the CLI's `optimize` flags plus the optimisation resolution).
struct OptimiserSettings {
    OptimizationOptions optimization;  ///< energy, annealing schedule, ascent
    int resolution = 100;              ///< rays per image side while optimising (paper: 100 or 1000)
    core::ScalarRange importanceRange; ///< scalar values mapped to importance 0 and 1 (scalar energy)
    bool framed = false;               ///< each view framed for its method (render::frameView), as the viewer shows it
    int views = 1;                     ///< "optimise view": also the visited views showing the most surface with the best (visibility energy)
};

/// @brief The parameter optimiser ("optimise alpha", ...): optimize::optimizeParameters (gradient ascent with golden-section line
///        searches) of the current method's optimised parameters (as its description says) at the
///        current camera. A method without any is only evaluated.
ViewOptimiser parameterOptimiser(const OptimiserSettings& settings);

/// @brief "optimise view": optimize::annealViewpoint from the current camera's angles on the radius
///        2.5 sphere, the parameters optimised at every proposal; returns the best view and, with
///        OptimiserSettings::views > 1 and the visibility energy, the view set of `optimize --views`
///        (optimize::chooseViewSet; each further view with its readable rule) and their union's
///        visibility at the optimisation resolution in the summary.
ViewOptimiser viewpointOptimiser(const OptimiserSettings& settings);

/// @brief "readable rule": optimize::loosestReadable of the current method with the readable
///        rule's parameter at its default, at the current camera (framed square, as the other optimisers
///        measure), for a 1000 x 1000 picture (optimize::kCoherenceResolution) and the settings'
///        minimum coherence: the rule render would choose for that picture.
ViewOptimiser readableRuleOptimiser(const OptimiserSettings& settings);

}  // namespace ivis::app
