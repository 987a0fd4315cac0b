/// @file legend_file.h
/// @brief `--legend-only FILE`: the colour bar alone, as SVG or PNG, for a figure.
#pragma once

#include <ivis/render/renderer.h>

#include <string>

namespace ivis::app {

/// @brief Checks that @a path names an .svg or .png file (before anything is read).
/// @throw InputError for another extension
void checkLegendFileName(const std::string& path);

/// @brief Writes the colour bar of @a options (colour map, scale, title, units, side) alone to
///        @a path, sized as beside a picture of options.width x options.height: vector SVG when
///        the name ends in .svg, else PNG (transparent when the options say so). Atomic.
/// @throw InputError for another extension
void writeLegendFile(const std::string& path, const render::RenderOptions& options);

}  // namespace ivis::app
