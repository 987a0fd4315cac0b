/// @file color_bar.h
/// @brief Draws a labelled vertical colour bar (the legend of a scalar field) at the right side of
///        an image.
/// @note Text is ASCII (see text_raster.h). The legend's backing makes every pixel it covers opaque,
///       so it reads on any background, a transparent one included.
#pragma once

#include <ivis/core/colormap.h>
#include <ivis/core/image.h>

#include <string>
#include <vector>

namespace ivis::core {

/// @brief Half-open pixel rectangle [x0, x1) x [y0, y1), row 0 at the top.
struct PixelRect {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;

    /// @brief True when pixel (x, y) lies inside.
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

/// @brief How the colour bar is sized.
struct ColorBarOptions {
    float heightFraction = 0.35f;  ///< gradient height / image height, in [0.05, 0.8]
    int textScale = 0;            ///< font scale factor (text_raster.h); 0 = 1 per 500 pixels of
                                  ///< the image's smaller side (rounded down), at least 1
    float backingOpacity = 0.85f; ///< how much the light backing hides the image under it, in [0,1]
};

/// @brief Where drawColorBar drew, clipped to the image.
struct ColorBarLayout {
    PixelRect backing;   ///< every pixel the legend changed lies in here
    PixelRect gradient;  ///< the colour ramp: top row ~ map.at(1), bottom row ~ map.at(0)
};

/// @brief Tick labels for lo, middle and hi ("%g" with the fewest significant digits, 3 to 9, that
///        tells them apart: "0.0931", "1.2e+03"); a single label when lo == hi.
std::vector<std::string> colorBarLabels(const ScalarRange& range);

/// @brief Draws the colour bar: a light backing, in the lower right corner, holding the
///        title line ("title [units]"; units on a second line when that is much wider than the
///        bar and its labels; no line when both are empty), the gradient of @a map with a thin frame, and ticks labelled by
///        colorBarLabels on its right; text and frame in dark grey.
/// @param image drawn into; sized from 128x128 to 4000x3000 and beyond (text clipped if too narrow)
/// @param range values at the bottom (lo) and top (hi) of the gradient
/// @throw ValueError for options outside their documented ranges
ColorBarLayout drawColorBar(Image& image, const Colormap& map, const ScalarRange& range, const std::string& title,
                            const std::string& units, const ColorBarOptions& options = {});

}  // namespace ivis::core
