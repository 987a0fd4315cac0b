/// @file file_bytes.h
/// @brief Reads a whole input file into memory, with one-line errors naming the file.
#pragma once

#include <string>

namespace ivis::core::detail {

/// The bytes of @a path.
/// @throw InputError "<path>: file not found", "is a directory, not a file", "not a regular file
///        (a pipe or device) ..." or "cannot read file (...)"
std::string readFileBytes(const std::string& path);

}  // namespace ivis::core::detail
