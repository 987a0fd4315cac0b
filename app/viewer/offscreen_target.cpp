#include "offscreen_target.h"

#include <ivis/core/errors.h>

#include <algorithm>

namespace ivis::app {

OffscreenTarget::OffscreenTarget()
    : mFramebuffer(newName(glGenFramebuffers)),
      mColour(newName(glGenTextures)),
      mRegion(newName(glGenTextures)),
      mDepth(newName(glGenRenderbuffers))
{
}

void OffscreenTarget::resize(int width, int height)
{
    if (width == mWidth && height == mHeight) return;
    glBindTexture(GL_TEXTURE_2D, mColour.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, mRegion.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, mDepth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mColour.id(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, mRegion.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDepth.id());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("creating the offscreen target");
    if (status != GL_FRAMEBUFFER_COMPLETE) throw GlError("the offscreen framebuffer is incomplete");
    mWidth = width;
    mHeight = height;
}

void OffscreenTarget::bindImages(int regionUnit, int colourUnit) const
{
    glBindImageTexture(GLuint(regionUnit), mRegion.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8UI);
    glBindImageTexture(GLuint(colourUnit), mColour.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
}

void OffscreenTarget::beginFrame(const glm::vec3& background) const
{
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mWidth, mHeight);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    const GLfloat clearColour[4] = {core::srgbFromLinear(background.x), core::srgbFromLinear(background.y),
                                    core::srgbFromLinear(background.z), 1.0f};
    const GLuint clearRegion[4] = {0, 0, 0, 0};
    const GLfloat clearDepth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, clearColour);
    glClearBufferuiv(GL_COLOR, 1, clearRegion);
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);
}

void OffscreenTarget::upload(const std::vector<std::uint8_t>& srgba, const std::vector<std::uint8_t>& region,
                             int width, int height)
{
    IVIS_CHECK(srgba.size() == std::size_t(width) * height * 4 && region.size() == std::size_t(width) * height);
    resize(width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const auto uploadRows = [&](const GlTexture& texture, GLenum format, const std::vector<std::uint8_t>& bytes,
                                int channels) {
        glBindTexture(GL_TEXTURE_2D, texture.id());
        const std::size_t rowBytes = std::size_t(width) * channels;
        for (int row = 0; row < height; ++row)  // GL rows start at the bottom
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, height - 1 - row, width, 1, format, GL_UNSIGNED_BYTE,
                            bytes.data() + std::size_t(row) * rowBytes);
    };
    uploadRows(mColour, GL_RGBA, srgba, 4);
    uploadRows(mRegion, GL_RED_INTEGER, region, 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    checkGl("uploading a picture");
}

void OffscreenTarget::blitTo(int x, int y, int width, int height) const
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mFramebuffer.id());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    const bool same = width == mWidth && height == mHeight;
    glBlitFramebuffer(0, 0, mWidth, mHeight, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT,
                      same ? GL_NEAREST : GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

std::vector<std::uint8_t> OffscreenTarget::readRows(GLenum attachment, GLenum format, int channels,
                                                   const char* what) const
{
    const std::size_t rowBytes = std::size_t(mWidth) * channels;
    std::vector<std::uint8_t> bytes(rowBytes * mHeight), rows(bytes.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mFramebuffer.id());
    glReadBuffer(attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, mWidth, mHeight, format, GL_UNSIGNED_BYTE, bytes.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    checkGl(what);
    for (int row = 0; row < mHeight; ++row)  // GL rows start at the bottom
        std::copy_n(bytes.data() + std::size_t(mHeight - 1 - row) * rowBytes, rowBytes, rows.data() + std::size_t(row) * rowBytes);
    return rows;
}

core::Image OffscreenTarget::readColour() const
{
    const std::vector<std::uint8_t> bytes = readRows(GL_COLOR_ATTACHMENT0, GL_RGBA, 4, "reading the colour back");
    float decode[256];
    for (int i = 0; i < 256; ++i) decode[i] = core::linearFromSrgb(float(i) / 255.0f);
    core::Image image(mWidth, mHeight);
    for (int row = 0; row < mHeight; ++row) {
        const std::uint8_t* src = bytes.data() + std::size_t(row) * mWidth * 4;
        for (int x = 0; x < mWidth; ++x)
            image.at(x, row) = glm::vec4(decode[src[4 * x]], decode[src[4 * x + 1]], decode[src[4 * x + 2]], 1.0f);
    }
    return image;
}

std::vector<std::uint8_t> OffscreenTarget::readRegion() const
{
    return readRows(GL_COLOR_ATTACHMENT1, GL_RED_INTEGER, 1, "reading the regions back");
}

core::Image regionImage(const std::vector<std::uint8_t>& region, int width, int height)
{
    const float grey[3] = {0.0f, core::linearFromSrgb(128.0f / 255.0f), 1.0f};
    core::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float g = grey[std::min<int>(region[std::size_t(y) * width + x], 2)];
            image.at(x, y) = glm::vec4(g, g, g, 1.0f);
        }
    return image;
}

}  // namespace ivis::app
