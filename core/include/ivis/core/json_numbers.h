/// @file json_numbers.h
/// @brief Numbers of the JSON files the program reads (view files, method JSON), checked before
///        they are converted.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace ivis::core {

/// @brief Whether @a json is a number that a float holds as a finite value (converting a larger
///        one is undefined behaviour; infinity in practice).
inline bool isFiniteFloat(const nlohmann::json& json)
{
    return json.is_number() && std::abs(json.get<double>()) <= double(std::numeric_limits<float>::max());
}

}  // namespace ivis::core
