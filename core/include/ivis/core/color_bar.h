/// @file color_bar.h
/// @brief The colour bar (legend of a scalar field): round ticks, a layout sized for a picture,
///        and its painting into an image margin or as SVG.
/// @note The bar never covers a picture: withColorBar grows the canvas by a margin on one side.
///       Text is drawn with Font::standard() (DejaVu Sans), so units may be any Unicode.
#pragma once

#include <ivis/core/color_scale.h>
#include <ivis/core/colormap.h>
#include <ivis/core/image.h>

#include <glm/vec4.hpp>

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

/// @brief A labelled value on the bar.
struct ColorBarTick {
    double value = 0.0;
    float position = 0.0f;  ///< along the bar, 0 = the colour map's low end
    std::string label;
    bool rangeEnd = false;  ///< marks an end of the scale's range
};

/// @brief Ticks of @a scale, ordered by value: both range ends (labelled with up to four
///        significant digits) and round values between them, five or more in all when the range
///        is not empty: multiples of 1, 2 or 5 times a power of ten on a linear scale, powers of
///        ten (then 2 and 5 times them, then every digit) on a log scale. Large and small
///        magnitudes are written as "1.5×10⁴".
std::vector<ColorBarTick> colorBarTicks(const ColorScale& scale);

/// @brief Which side of the picture the colour bar's margin is on.
enum class LegendSide { Right, Left, Bottom };

/// @brief "right", "left", "bottom".
/// @throw InputError for another name
LegendSide legendSideFromName(const std::string& name);

/// @brief What a colour bar shows.
struct ColorBarContent {
    std::string colormap = kDefaultColormap;
    ColorScale scale;
    std::string title;  ///< e.g. the scalar's name; may be empty
    std::string units;  ///< shown as "[units]" after the title; may be empty
};

/// @brief A colour bar laid out in its own block: every position is relative to the block's
///        top-left corner.
struct ColorBarDrawing {
    /// @brief One line of text; x is where its anchor is.
    struct Text {
        int x = 0;
        int baseline = 0;
        std::string text;
        bool centred = false;  ///< x is the text's centre (else its start)
    };

    int width = 0;
    int height = 0;
    int fontPixels = 0;
    bool vertical = true;           ///< colour map's low end at the bottom (else at the left)
    PixelRect gradient;             ///< the colour ramp
    std::vector<PixelRect> ink;     ///< frame and tick marks, drawn dark
    std::vector<Text> labels;       ///< title and tick labels, drawn dark
    std::vector<ColorBarTick> ticks;  ///< the ticks whose labels were kept
};

/// @brief Lays out the bar of @a content for a @a pictureWidth x @a pictureHeight picture on
///        @a side: the bar is 60% of the picture's side along it, the text 1/45 of that side (at
///        least 12 pixels); interior tick labels that would touch another label are dropped.
/// @throw ValueError for a picture smaller than 1x1; InputError when no font is found
ColorBarDrawing layOutColorBar(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side);

/// @brief Paints @a drawing with its top-left corner at pixel (x, y) of @a image (the margin's
///        background is left as it is).
void paintColorBar(Image& image, int x, int y, const ColorBarDrawing& drawing, const ColorBarContent& content);

/// @brief The margin's extent across the bar (width beside, height below the picture) that
///        withColorBar gives @a content: the widest of several (e.g. the frames of a series) is the
///        minimum that makes their canvases the same size.
int colorBarMargin(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side);

/// @brief @a picture with the colour bar in a margin on @a side: a new canvas, the margin filled
///        with @a background (premultiplied linear RGBA) and at least @a minimumMargin pixels
///        across, the picture's pixels unchanged.
Image withColorBar(const Image& picture, const ColorBarContent& content, LegendSide side, const glm::vec4& background,
                   int minimumMargin = 0);

/// @brief The colour bar alone as a standalone SVG document (vector gradient and text, the same
///        layout as the picture's), sized for a @a pictureWidth x @a pictureHeight picture.
std::string colorBarSvg(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side);

/// @brief The colour bar alone as an image on @a background, sized as for the picture.
Image colorBarImage(const ColorBarContent& content, int pictureWidth, int pictureHeight, LegendSide side,
                    const glm::vec4& background);

}  // namespace ivis::core
