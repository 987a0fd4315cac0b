/// @file file_extension.h
/// @brief A file's extension as the program compares it: in lower case, so that bunny.PLY and
///        figure.SVG are read and written as bunny.ply and figure.svg are.
#pragma once

#include <string>

namespace ivis::core {

/// @brief The extension of @a path's file name with its dot, in lower case (".vtp"), or "".
std::string lowerCaseExtension(const std::string& path);

}  // namespace ivis::core
