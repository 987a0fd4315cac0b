/// @file image.h
/// @brief RGBA float images in linear light, named float channels for EXR, and the sRGB transfer
///        function.
/// @note Colours are premultiplied by alpha (the OpenEXR convention); row 0 is the TOP row.
#pragma once

#include <ivis/core/large_block.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ivis::core {

/// @brief sRGB electro-optical transfer function (IEC 61966-2-1): encoded [0,1] -> linear [0,1].
float linearFromSrgb(float encoded);

/// @brief Inverse of linearFromSrgb: linear [0,1] -> sRGB-encoded [0,1].
float srgbFromLinear(float linear);

/// @brief The 8-bit sRGB level of a linear value, round(255 srgbFromLinear(linear)) clamped to
///        [0, 255] (0 for NaN), read from tables that give that formula's level at every float.
std::uint8_t srgbByteFromLinear(float linear);

/// @brief linearFromSrgb applied to each channel.
glm::vec3 linearFromSrgb(const glm::vec3& encoded);

/// @brief Storage of an image's pixels (large ones faulted in on every core: large_block.h).
using PixelBuffer = std::vector<glm::vec4, LargeBlockAllocator<glm::vec4>>;
/// @brief Storage of one layer channel (large ones faulted in on every core: large_block.h).
using Channel = std::vector<float, LargeBlockAllocator<float>>;

/// @brief A width x height grid of linear-light RGBA pixels (premultiplied alpha), row 0 at the top.
class Image {
public:
    Image() = default;
    /// @brief Image of @a width x @a height pixels, all set to @a fill.
    /// @throw ValueError for a negative size
    Image(int width, int height, const glm::vec4& fill = glm::vec4(0.0f));

    /// @brief Number of columns.
    int width() const { return mWidth; }
    /// @brief Number of rows.
    int height() const { return mHeight; }
    /// @brief True when (x, y) is a pixel of this image.
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < mWidth && y < mHeight; }

    /// @brief Pixel in column @a x, row @a y (row 0 at the top); must be contained.
    glm::vec4& at(int x, int y);
    /// @brief Pixel in column @a x, row @a y (row 0 at the top); must be contained.
    const glm::vec4& at(int x, int y) const;

    /// @brief Composites @a color (linear RGB, not premultiplied) with @a opacity over pixel
    ///        (x, y); pixels outside the image are ignored.
    void blendOver(int x, int y, const glm::vec3& color, float opacity = 1.0f);

    /// @brief All pixels, row-major from the top row.
    const PixelBuffer& pixels() const { return mPixels; }
    /// @brief All pixels, row-major from the top row.
    PixelBuffer& pixels() { return mPixels; }

private:
    int mWidth = 0;
    int mHeight = 0;
    PixelBuffer mPixels;
};

/// @brief Extra per-pixel float channels written beside RGBA into an EXR ("depth", "region",
///        "triangle", "P.X", "scalar", ...); each is width * height values, row-major from the top.
/// @note References returned by add() and channel() stay valid when more channels are added.
class ImageLayers {
public:
    /// @brief No channels yet; every channel added will have @a width x @a height values.
    /// @throw ValueError for a negative size
    ImageLayers(int width, int height);

    /// @brief Adds channel @a name with every value set to @a fill and returns it.
    /// @throw ValueError for an empty or duplicate name, or R, G, B, A (those hold the colour)
    Channel& add(const std::string& name, float fill = 0.0f);
    /// @brief The channel called @a name. @throw ValueError when there is none
    Channel& channel(const std::string& name);
    /// @brief The channel called @a name. @throw ValueError when there is none
    const Channel& channel(const std::string& name) const;
    /// @brief All channels, sorted by name.
    const std::map<std::string, Channel>& channels() const { return mChannels; }

    /// @brief Number of columns of every channel.
    int width() const { return mWidth; }
    /// @brief Number of rows of every channel.
    int height() const { return mHeight; }

private:
    int mWidth = 0;
    int mHeight = 0;
    std::map<std::string, Channel> mChannels;
};

}  // namespace ivis::core
