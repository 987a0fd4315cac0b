/// @file offscreen_target.h
/// @brief The framebuffer the viewer renders into: sRGB-encoded 8-bit colour, the region of every
///        pixel (0 background, 1 direct, 2 indirect) and depth.
/// @note Needs a current OpenGL 4.3 core context; not thread-safe.
#pragma once

#include "gl_objects.h"

#include <ivis/core/image.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace ivis::app {

/// @brief Offscreen colour + region + depth target.
class OffscreenTarget {
public:
    /// @brief Creates the (empty) GL objects; resize() allocates them.
    OffscreenTarget();
    /// @brief Reallocates the attachments at @a width x @a height pixels (nothing when unchanged).
    /// @throw GlError when the framebuffer is incomplete
    void resize(int width, int height);
    /// @brief Binds the target for drawing both attachments with depth test, and clears it to
    ///        @a background (linear RGB, stored sRGB-encoded), region 0 and depth 1.
    void beginFrame(const glm::vec3& background) const;
    /// @brief Binds the region (read-only, r8ui) and the colour (read-write, rgba8) to image units
    ///        @a regionUnit and @a colourUnit, for a pass that edits the colour in place.
    void bindImages(int regionUnit, int colourUnit) const;
    /// @brief Resizes the target to @a width x @a height and fills it with a picture made elsewhere:
    ///        @a srgba 8-bit sRGB-encoded RGBA and @a region one byte per pixel, both row 0 at the top.
    void upload(const std::vector<std::uint8_t>& srgba, const std::vector<std::uint8_t>& region, int width, int height);
    /// @brief Copies the colour into the bound draw framebuffer's rectangle (x, y, w, h).
    void blitTo(int x, int y, int width, int height) const;
    /// @brief The colour as a linear image (decoded from the 8-bit sRGB values), row 0 at the top.
    core::Image readColour() const;
    /// @brief The regions (0 background, 1 direct, 2 indirect), row 0 at the top.
    std::vector<std::uint8_t> readRegion() const;
    /// @brief Size of the offscreen target in pixels.
    int width() const { return mWidth; }
    int height() const { return mHeight; }

private:
    /// The pixels of @a attachment (@a channels bytes each in @a format), row 0 at the top.
    std::vector<std::uint8_t> readRows(GLenum attachment, GLenum format, int channels, const char* what) const;

    GlFramebuffer mFramebuffer;
    GlTexture mColour;
    GlTexture mRegion;
    GlRenderbuffer mDepth;
    int mWidth = 0;
    int mHeight = 0;
};

/// @brief Regions as readRegion() returns them (@a width x @a height) shown as grey levels: 0
///        background, 128 direct, 255 indirect (sRGB-encoded values in the PNG).
core::Image regionImage(const std::vector<std::uint8_t>& region, int width, int height);

}  // namespace ivis::app
