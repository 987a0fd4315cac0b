#include <ivis/core/image.h>

#include <ivis/core/errors.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace ivis::core {
namespace {
void checkSize(int width, int height)
{
    if (width < 0 || height < 0)
        throw ValueError("invalid image size " + std::to_string(width) + "x" + std::to_string(height));
}
}  // namespace

float linearFromSrgb(float encoded)
{
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

float srgbFromLinear(float linear)
{
    return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 linearFromSrgb(const glm::vec3& encoded)
{
    return {linearFromSrgb(encoded.r), linearFromSrgb(encoded.g), linearFromSrgb(encoded.b)};
}

Image::Image(int width, int height, const glm::vec4& fill) : mWidth(width), mHeight(height)
{
    checkSize(width, height);
    mPixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

glm::vec4& Image::at(int x, int y)
{
    IVIS_DCHECK(contains(x, y));
    return mPixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) + static_cast<std::size_t>(x)];
}

const glm::vec4& Image::at(int x, int y) const
{
    IVIS_DCHECK(contains(x, y));
    return mPixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(mWidth) + static_cast<std::size_t>(x)];
}

void Image::blendOver(int x, int y, const glm::vec3& color, float opacity)
{
    if (!contains(x, y)) return;
    glm::vec4& pixel = at(x, y);
    pixel = glm::vec4(color * opacity, opacity) + pixel * (1.0f - opacity);
}

ImageLayers::ImageLayers(int width, int height) : mWidth(width), mHeight(height)
{
    checkSize(width, height);
}

Channel& ImageLayers::add(const std::string& name, float fill)
{
    if (name.empty() || name == "R" || name == "G" || name == "B" || name == "A")
        throw ValueError("invalid image channel name '" + name + "' (R, G, B, A hold the colour)");
    const auto [it, inserted] = mChannels.try_emplace(
        name, static_cast<std::size_t>(mWidth) * static_cast<std::size_t>(mHeight), fill);
    if (!inserted) throw ValueError("image channel '" + name + "' added twice");
    return it->second;
}

Channel& ImageLayers::channel(const std::string& name)
{
    return const_cast<Channel&>(std::as_const(*this).channel(name));
}

const Channel& ImageLayers::channel(const std::string& name) const
{
    const auto it = mChannels.find(name);
    if (it == mChannels.end()) throw ValueError("no image channel '" + name + "'");
    return it->second;
}

}  // namespace ivis::core
