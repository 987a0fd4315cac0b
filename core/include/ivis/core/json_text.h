/// @file json_text.h
/// @brief JSON as text for files and stdout, whatever bytes the names read from files hold.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <exception>
#include <string>

namespace ivis::core {

/// @brief @a json as text (@a indent spaces per level; -1: one line), each byte sequence that is
///        not UTF-8 (an array named in Latin-1, as older tools write them) as U+FFFD, where
///        nlohmann::json would throw.
inline std::string jsonText(const nlohmann::json& json, int indent = -1)
{
    return json.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// @brief What went wrong reading a JSON file, in words on one line: @a error's message without
///        nlohmann::json's "[json.exception.type_error.302] " prefix, its newlines as spaces.
inline std::string jsonErrorWords(const std::exception& error)
{
    std::string why = error.what();
    std::replace(why.begin(), why.end(), '\n', ' ');  // one line, whatever the parser quotes
    if (why.rfind("[json.exception.", 0) == 0 && why.find("] ") != std::string::npos)
        why = why.substr(why.find("] ") + 2);
    return why;
}

}  // namespace ivis::core
