/// @file json_text.h
/// @brief JSON as text for files and stdout, whatever bytes the names read from files hold.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace ivis::core {

/// @brief @a json as text (@a indent spaces per level; -1: one line), each byte sequence that is
///        not UTF-8 (an array named in Latin-1, as older tools write them) as U+FFFD, where
///        nlohmann::json would throw.
inline std::string jsonText(const nlohmann::json& json, int indent = -1)
{
    return json.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace ivis::core
