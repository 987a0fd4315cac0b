#include <ivis/render/outline.h>

#include <ivis/render/pixel_mapping.h>

#include <tbb/parallel_for.h>

#include <algorithm>

namespace ivis::render {

std::vector<std::uint8_t> outlineMask(const core::Channel& region, int width, int height, int radius)
{
    const std::size_t w = std::size_t(width);
    auto isDirect = [&](std::size_t index) { return region[index] == float(Region::Direct); };
    // Per row, each pixel's horizontal distance to the nearest pixel of its row that is not
    // direct, capped at radius + 1 (the positions left and right of the row count as not direct).
    const int far = radius + 1;
    std::vector<std::uint16_t> across(w * std::size_t(height));
    tbb::parallel_for(0, height, [&](int y) {
        std::uint16_t* row = &across[std::size_t(y) * w];
        int distance = 0;  // at x = -1
        for (std::size_t x = 0; x < w; ++x) {
            distance = isDirect(std::size_t(y) * w + x) ? std::min(distance + 1, far) : 0;
            row[x] = std::uint16_t(distance);
        }
        distance = 0;  // at x = width
        for (std::size_t x = w; x-- > 0;) {
            distance = row[x] == 0 ? 0 : std::min(distance + 1, far);
            row[x] = std::min(row[x], std::uint16_t(distance));
        }
    });
    // A direct pixel is on the outline when some row dy away (|dy| <= radius) has a pixel that is
    // not direct within sqrt(radius^2 - dy^2) of its column, or the disc reaches past the top or
    // the bottom of the picture.
    std::vector<std::uint8_t> mask(w * std::size_t(height), 0);
    tbb::parallel_for(0, height, [&](int y) {
        const bool nearTopOrBottom = y < radius || y >= height - radius;
        for (std::size_t x = 0; x < w; ++x) {
            const std::size_t index = std::size_t(y) * w + x;
            if (!isDirect(index)) continue;
            bool edge = nearTopOrBottom;
            for (int dy = -radius; dy <= radius && !edge; ++dy) {
                const int d = across[std::size_t(y + dy) * w + x];
                edge = d * d + dy * dy <= radius * radius;
            }
            mask[index] = edge;
        }
    });
    return mask;
}

void drawOutline(core::Image& image, const core::Channel& region, int radius)
{
    const std::vector<std::uint8_t> mask = outlineMask(region, image.width(), image.height(), radius);
    tbb::parallel_for(0, image.height(), [&](int y) {
        for (int x = 0; x < image.width(); ++x)
            if (mask[std::size_t(y) * image.width() + x]) image.blendOver(x, y, glm::vec3(0.05f), 0.85f);
    });
}

}  // namespace ivis::render
