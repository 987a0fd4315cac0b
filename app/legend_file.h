/// @file legend_file.h
/// @brief `--legend-only FILE`: the colour bar alone, as SVG or PNG, for a figure.
#pragma once

#include <ivis/render/renderer.h>

#include <string>

namespace ivis::app {

/// @brief Writes the colour bar of @a options (colour map, scale, title, units, side) alone to
///        @a path, sized as beside a picture of options.width x options.height: vector SVG when
///        the name ends in .svg (any case), else PNG (transparent when the options say so). Atomic.
/// @note The name's extension is checked before anything is read (checkOutputFiles).
void writeLegendFile(const std::string& path, const render::RenderOptions& options);

}  // namespace ivis::app
