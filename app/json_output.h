/// @file json_output.h
/// @brief JSON forms of the engine's results, and writing a JSON file atomically.
#pragma once

#include <ivis/optimize/coherence.h>
#include <ivis/optimize/viewpoint_annealing.h>

#include <nlohmann/json.hpp>

#include <string>

namespace ivis::app {

/// @brief One visited view: angles, field of view, energy, front-only energy, accepted, parameters.
nlohmann::json visitedViewJson(const optimize::VisitedView& view);

/// @brief METHOD.md's measures of one view: visibility, paper_literal, front_visibility,
///        coherence (optimize::mappingCoherence's value) and, when @a withReveal, reveal (total,
///        direct, per_region).
nlohmann::json measuresJson(const optimize::EnergyValue& value, double coherence, bool withReveal);

/// @brief Writes @a text to @a path through a temporary file.
/// @throw InputError naming the path when it cannot be written
void writeTextFile(const std::string& text, const std::string& path);

/// @brief Writes @a json (indented) to @a path through a temporary file.
/// @throw InputError naming the path when it cannot be written
void writeJsonFile(const nlohmann::json& json, const std::string& path);

}  // namespace ivis::app
