/// @file color_bar_overlay.h
/// @brief The CPU renderer's colour bar (core::layOutColorBar, same font and ticks) in a margin of
///        the viewer's window: the picture gets the rest of the window, the bar is an uploaded
///        texture drawn behind the panel.
/// @note Needs a current OpenGL context; not thread-safe.
#pragma once

#include "gl_objects.h"

#include <ivis/core/color_bar.h>

#include <imgui.h>

#include <string>

namespace ivis::app {

/// @brief Where the picture goes in a window of fbWidth x fbHeight framebuffer pixels.
struct PictureViewport {
    int x = 0;  ///< OpenGL window coordinates: origin at the bottom left
    int y = 0;
    int width = 0;
    int height = 0;
};

/// @brief The colour bar beside the viewer's picture.
class ColorBarOverlay {
public:
    ColorBarOverlay();
    /// @brief Lays the bar of @a content out on @a side of the part of a @a fbWidth x @a fbHeight
    ///        window right of @a left (the panel's strip) (re-drawing its texture only when
    ///        something changed) and returns the picture's part; that whole part when @a shown is false.
    PictureViewport place(const core::ColorBarContent& content, core::LegendSide side, bool shown, int left,
                          int fbWidth, int fbHeight);
    /// @brief Draws the bar placed last into @a drawList (ImGui coordinates = framebuffer pixels /
    ///        @a framebufferScale); nothing when hidden.
    void draw(ImDrawList& drawList, const ImVec2& framebufferScale) const;

private:
    GlTexture mTexture;
    std::string mKey;  ///< what the texture shows (content, side, size)
    bool mShown = false;
    int mX = 0, mY = 0, mWidth = 0, mHeight = 0;  ///< the bar's rectangle, framebuffer pixels, top-left origin
};

}  // namespace ivis::app
