/// @file method_json.h
/// @brief A method and its parameter values as JSON: {"method": name, key: value or [values]...},
///        keyed as the method's description; read back with the same checks as makeMethod().
#pragma once

#include <ivis/render/method.h>

#include <nlohmann/json.hpp>

namespace ivis::render {

/// @brief The method's name and every parameter (a number for one component, else an array).
nlohmann::json methodToJson(const Method& method);

/// @brief The method described by @a json (missing parameters take their defaults).
/// @throw InputError for a missing or unknown name, an unknown key or a value that is not a
///        finite float;
///        ValueError for values out of bounds
MethodPtr methodFromJson(const nlohmann::json& json);

}  // namespace ivis::render
