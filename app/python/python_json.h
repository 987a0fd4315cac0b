/// @file python_json.h
/// @brief JSON values handed to Python as the objects json.loads gives (dicts, lists, numbers).
#pragma once

#include <ivis/core/json_text.h>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

namespace ivis::python {

/// @brief @a json as the Python object json.loads would give.
inline pybind11::object fromJson(const nlohmann::json& json)
{
    return pybind11::module_::import("json").attr("loads")(core::jsonText(json));
}

}  // namespace ivis::python
