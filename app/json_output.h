/// @file json_output.h
/// @brief JSON forms of the engine's results, and writing a JSON file atomically.
#pragma once

#include <ivis/optimize/viewpoint_annealing.h>

#include <nlohmann/json.hpp>

#include <string>

namespace ivis::app {

/// @brief One visited view: angles, energy, front-only energy, accepted, parameters.
nlohmann::json visitedViewJson(const optimize::VisitedView& view);

/// @brief Writes @a json (indented) to @a path through a temporary file.
/// @throw InputError naming the path when it cannot be written
void writeJsonFile(const nlohmann::json& json, const std::string& path);

}  // namespace ivis::app
