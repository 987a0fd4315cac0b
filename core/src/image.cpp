#include <ivis/core/image.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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

/// srgbByteFromLinear by its formula.
int srgbLevelByFormula(float linear)
{
    const float encoded = srgbFromLinear(linear);
    return int(std::lround((encoded > 0.0f ? std::min(encoded, 1.0f) : 0.0f) * 255.0f));
}

/// Where srgbLevelByFormula steps. The formula rises monotonically over the floats of [0, 1]
/// (checked at every one of them), so a level is the bin's level at its start, raised past each
/// level whose least value the linear value reaches.
struct SrgbLevels {
    static constexpr int kBins = 4096;  ///< bins of [0, 1]; a bin spans at most about one level
    std::array<std::uint8_t, kBins> binStart{};
    std::array<float, 256> levelStart{};  ///< the least float of [0, 1] at each level

    SrgbLevels()
    {
        const auto bitsOf = [](float f) { std::uint32_t b; std::memcpy(&b, &f, sizeof b); return b; };
        const auto floatOf = [](std::uint32_t b) { float f; std::memcpy(&f, &b, sizeof f); return f; };
        for (int level = 1; level < 256; ++level) {  // bisection over the floats' bits, ordered as the floats
            std::uint32_t below = 0, at = bitsOf(1.0f);
            while (at - below > 1) {
                const std::uint32_t middle = below + (at - below) / 2;
                (srgbLevelByFormula(floatOf(middle)) >= level ? at : below) = middle;
            }
            levelStart[std::size_t(level)] = floatOf(at);
        }
        for (int bin = 0; bin < kBins; ++bin)
            binStart[std::size_t(bin)] = std::uint8_t(srgbLevelByFormula(float(bin) / float(kBins)));
    }
};

}  // namespace

std::uint8_t srgbByteFromLinear(float linear)
{
    static const SrgbLevels levels;
    if (!(linear > 0.0f)) return 0;  // NaN too
    if (linear >= 1.0f) return 255;
    int level = levels.binStart[std::size_t(linear * float(SrgbLevels::kBins))];
    while (level < 255 && linear >= levels.levelStart[std::size_t(level + 1)]) ++level;
    return std::uint8_t(level);
}

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
