/// @file atomic_file.h
/// @brief Writes an output through a temporary file in the same folder and renames it into place,
///        so that a reader never sees a partial file.
#pragma once

#include <functional>
#include <string>

namespace ivis::core {

/// @brief Calls @a write with a temporary path beside @a path, then renames it to @a path.
///        On any failure the temporary is removed and InputError "<path>: cannot write (<why>)" is
///        thrown; an existing file at @a path is left untouched.
/// @param write writes the complete content to the path it is given; throws on failure
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace ivis::core
