/// @file several_views.h
/// @brief `optimize --views N`: besides the best view, the visited views that together with it show
///        the most surface (optimize/view_set.h), each made readable as the best view is, drawn
///        side by side with one colour bar, and measured together (docs/optimisation.md, "Several views").
#pragma once

#include <ivis/optimize/energy.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/renderer.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ivis::app {

/// @brief One view of the set: its camera at the picture's size, its method and its picture.
struct ChosenView {
    core::Camera camera;
    render::MethodPtr method;
    render::RenderResult picture;
};

/// @brief The set of views and what they show together.
struct SeveralViews {
    std::vector<ChosenView> views;  ///< the best view first
    core::Image figure;             ///< their pictures side by side, with one colour bar when the options ask for one
    nlohmann::json json;            ///< {"views": [{theta, phi, fov_y_deg, params, visibility, coherence}], "union": {...}}
    std::string line;               ///< one line for the log
};

/// @brief Chooses up to @a count views of @a result on @a evaluator's surface voxels (the
///        visibility energy), the best one first with its @a bestPicture; gives each further view
///        its loosest readable setting (@a annealing's readableResolution, minCoherence), frames it
///        for @a options' size when @a framed (else keeps its field of view) and renders it;
///        measures each picture and their union on @a measure.
/// @throw ValueError unless @a evaluator measures the visibility energy
SeveralViews renderSeveralViews(const render::RenderScene& scene, const optimize::AnnealingResult& result,
                                const optimize::EnergyEvaluator& evaluator, const optimize::EnergyEvaluator& measure,
                                const optimize::AnnealingOptions& annealing, bool framed,
                                const render::RenderOptions& options, const core::Camera& bestCamera,
                                const render::RenderResult& bestPicture, int count);

}  // namespace ivis::app
