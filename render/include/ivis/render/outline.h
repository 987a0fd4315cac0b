/// @file outline.h
/// @brief The dark outline round the directly visible object: its direct pixels within a disc of
///        radius r of a pixel that is not direct, or of the picture's edge.
#pragma once

#include <ivis/core/image.h>

#include <cstdint>
#include <vector>

namespace ivis::render {

/// @brief Per pixel of a @a width x @a height picture (row-major), 1 where the pixel is direct
///        (@a region holds Region values) and some pixel within Euclidean distance @a radius of it
///        is not, a position outside the picture counting as not direct; 0 elsewhere.
std::vector<std::uint8_t> outlineMask(const core::Channel& region, int width, int height, int radius);

/// @brief Darkens the pixels of outlineMask() in @a image (85% toward near black).
void drawOutline(core::Image& image, const core::Channel& region, int radius);

}  // namespace ivis::render
