#include "color_bar_overlay.h"

#include <ivis/core/image.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

namespace ivis::app {

ColorBarOverlay::ColorBarOverlay() : mTexture(newName(glGenTextures)) {}

PictureViewport ColorBarOverlay::place(const core::ColorBarContent& content, core::LegendSide side, bool shown,
                                       int left, int fbWidth, int fbHeight)
{
    mShown = shown;
    const int width = fbWidth - left;  // the part the picture and the bar share
    if (!shown) return {left, 0, width, fbHeight};
    const bool bottom = side == core::LegendSide::Bottom;
    const int margin = core::colorBarMargin(content, width, fbHeight, side);
    const int pictureWidth = bottom ? width : std::max(16, width - margin);
    const int pictureHeight = bottom ? std::max(16, fbHeight - margin) : fbHeight;

    std::ostringstream key;
    key << content.colormap << '|' << content.scale.range.lo << '|' << content.scale.range.hi << '|' << content.scale.log
        << content.scale.invert << '|' << content.title << '|' << content.units << '|' << int(side) << '|' << pictureWidth
        << 'x' << pictureHeight;
    if (key.str() != mKey) {
        const core::Image bar = core::colorBarImage(content, pictureWidth, pictureHeight, side, glm::vec4(1.0f));
        std::vector<std::uint8_t> bytes(std::size_t(bar.width()) * bar.height() * 4);
        for (int y = 0; y < bar.height(); ++y)
            for (int x = 0; x < bar.width(); ++x)
                for (int c = 0; c < 4; ++c) {
                    const float linear = bar.at(x, y)[c];
                    const float encoded = c == 3 ? linear : core::srgbFromLinear(linear);
                    bytes[(std::size_t(y) * bar.width() + x) * 4 + c] = std::uint8_t(std::lround(encoded * 255.0f));
                }
        glBindTexture(GL_TEXTURE_2D, mTexture.id());
        textureParameters(GL_TEXTURE_2D, GL_NEAREST);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, bar.width(), bar.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        mKey = key.str();
        mWidth = bar.width();
        mHeight = bar.height();
    }
    mX = left + (side == core::LegendSide::Right ? width - mWidth : 0);
    mY = bottom ? fbHeight - mHeight : (fbHeight - mHeight) / 2;
    if (side == core::LegendSide::Left) return {left + mWidth, 0, width - mWidth, fbHeight};
    if (bottom) return {left, mHeight, width, fbHeight - mHeight};
    return {left, 0, width - mWidth, fbHeight};
}

void ColorBarOverlay::draw(ImDrawList& drawList, const ImVec2& framebufferScale) const
{
    if (!mShown) return;
    const ImVec2 topLeft(float(mX) / framebufferScale.x, float(mY) / framebufferScale.y);
    const ImVec2 bottomRight(float(mX + mWidth) / framebufferScale.x, float(mY + mHeight) / framebufferScale.y);
    drawList.AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(mTexture.id())), topLeft, bottomRight);
}

}  // namespace ivis::app
