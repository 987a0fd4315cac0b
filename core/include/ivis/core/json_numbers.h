/// @file json_numbers.h
/// @brief Numbers read from JSON files, checked before they are converted (the file readers').
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace ivis::core {

/// @brief Whether @a json is a number that a float holds as a finite value (converting a larger
///        one would give infinity).
inline bool isFiniteFloat(const nlohmann::json& json)
{
    return json.is_number() && std::abs(json.get<double>()) <= double(std::numeric_limits<float>::max());
}

}  // namespace ivis::core
