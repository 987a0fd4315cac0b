/// @file embedded_shaders.h
/// @brief The files of assets/shaders/, embedded into the program at build time: CMake runs
///        assets/embed_files.cmake whenever one of them changes, which writes embedded_shaders.cpp (in the
///        build folder) with each file's text as a raw string literal.
#pragma once

#include <vector>

namespace ivis::app::shaders {

/// @brief One embedded file: its name in assets/shaders/ and its text.
struct EmbeddedFile {
    const char* name;  ///< e.g. "method_mirror.glsl"
    const char* text;
};

/// @brief Every file of assets/shaders/ listed in app/CMakeLists.txt, in that order.
const std::vector<EmbeddedFile>& embeddedFiles();

}  // namespace ivis::app::shaders
