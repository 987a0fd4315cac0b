/// @file version.h
/// @brief What `--version` prints: the program's version and those of the libraries it was built with.
#pragma once

#include <string>

namespace ivis::app {

/// @brief "inversevis 0.1.0 (OpenVDB 10.0.1, Embree 3.13.5, OpenEXR 3.1.5)" for @a program.
std::string versionText(const std::string& program);

}  // namespace ivis::app
