/// @file json_output.h
/// @brief JSON forms of the engine's results, and writing a JSON file atomically.
#pragma once

#include <ivis/optimize/coherence.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/hot_spot_shape.h>
#include <ivis/optimize/viewpoint_annealing.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ivis::app {

/// @brief One visited view: angles, field of view, energy, front-only energy, accepted, parameters
///        and, for a finalist, its energy on the finalists' evaluator.
nlohmann::json visitedViewJson(const optimize::VisitedView& view);

/// @brief "readable rule: stable_shift 0.02, estimated coherence 0.9931 on 20051 sampled pairs of a
///        1000x1000 picture".
std::string readableSettingLine(const optimize::ReadableSetting& setting);

/// @brief "hot-spot rule: judged view 3 is the best whose every hot spot reads as one place (82% of
///        the best view's energy)", or that none did and the nearest to it was taken.
std::string hotSpotChoiceLine(const optimize::HotSpotChoice& choice);

/// @brief The measures (docs/measures.md) of one view: visibility, voxel_visibility, paper_literal, front_visibility,
///        coherence (optimize::mappingCoherence's value) and, when @a withReveal, reveal (total,
///        direct, per_region).
nlohmann::json measuresJson(const optimize::EnergyValue& value, double coherence, bool withReveal);

/// @brief Adds each hot spot's shape in a picture's @a layers (optimize/hot_spot_shape.h) to
///        @a measures as reveal.shapes, [{pixels, largest_share, outline_ratio}, ...], when they
///        hold a reveal measured by @a evaluator.
void addHotSpotShapes(nlohmann::json& measures, const optimize::EnergyEvaluator& evaluator,
                      const core::ImageLayers& layers);

/// @brief measuresJson of a rendered picture (`render --measure`): @a method traced again from
///        @a camera with @a resolution rays per side, its landings counted on the 200^3 grid of docs/measures.md;
///        with a scalar, the reveal of the importance over @a importanceRange and each hot spot's
///        shape in the picture's @a layers (reveal.shapes); and surface_pixels (direct and
///        indirect) with even_bound, what as many points spread evenly would measure.
///        With @a unseen, also the unseen map of the same tracing (optimize/unseen_map.h), its
///        panels @a resolution pixels square.
nlohmann::json pictureMeasuresJson(const render::RenderScene& scene, const core::Camera& camera,
                                   const render::MethodPtr& method, int resolution,
                                   const core::ScalarRange& importanceRange, double coherence,
                                   const core::ImageLayers& layers, core::Image* unseen = nullptr);

/// @brief One line of pictureMeasuresJson's figures for the log ("surface visibility 0.941 (front 0.285), ...").
std::string measuresLine(const nlohmann::json& measures);

/// @brief Writes @a text to @a path through a temporary file.
/// @throw InputError naming the path when it cannot be written
void writeTextFile(const std::string& text, const std::string& path);

/// @brief Writes @a json (indented) to @a path through a temporary file.
/// @throw InputError naming the path when it cannot be written
void writeJsonFile(const nlohmann::json& json, const std::string& path);

}  // namespace ivis::app
