/// @file text_raster.h
/// @brief Draws ASCII text into an Image with an embedded 5x9 bitmap font (no font files needed).
/// @note Characters outside 32..126 (UTF-8 bytes included) are drawn as '?'.
#pragma once

#include <ivis/core/image.h>

#include <glm/vec3.hpp>

#include <string>

namespace ivis::core {

/// @brief Glyph box at scale 1: 5 columns; 9 rows = 7 above the baseline (capitals, digits) and 2
///        for descenders (g, j, p, q, y, ',', '_').
inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 9;
/// @brief Rows of a capital letter or digit at scale 1 (the rows above the baseline).
inline constexpr int kCapHeight = 7;
/// @brief Distance between the left edges of consecutive glyphs at scale 1 (1 column of spacing).
inline constexpr int kGlyphAdvance = 6;

/// @brief Width in pixels of @a text drawn at @a scale, from the first glyph's left column to the
///        last glyph's right column (no trailing spacing); 0 for "".
/// @throw ValueError for scale < 1
int textWidth(const std::string& text, int scale = 1);

/// @brief Height in pixels of one line drawn at @a scale (kGlyphHeight * scale).
/// @throw ValueError for scale < 1
int textHeight(int scale = 1);

/// @brief True when the glyph of @a c has its pixel at (column, row) set (both at scale 1; false
///        outside the 5x9 box).
bool glyphPixel(char c, int column, int row);

/// @brief Draws @a text with its glyph box's top-left corner at pixel (x, y), each font pixel as a
///        @a scale x @a scale square of opaque linear @a color; pixels outside the image are skipped.
/// @throw ValueError for scale < 1
void drawText(Image& image, int x, int y, const std::string& text, const glm::vec3& color, int scale = 1);

}  // namespace ivis::core
