/// @file embedded_colormaps.h
/// @brief The published colour-map tables of assets/colormaps/, embedded at build time (CMake runs
///        assets/embed_files.cmake whenever one changes): each file's name and text.
/// @note Internal to core: colormap.cpp reads them.
#pragma once

#include <vector>

namespace ivis::core::detail {

/// @brief One embedded table: its file name ("magma.txt") and its text.
struct EmbeddedFile {
    const char* name;
    const char* text;
};

/// @brief Every table listed in core/CMakeLists.txt.
const std::vector<EmbeddedFile>& embeddedFiles();

}  // namespace ivis::core::detail
