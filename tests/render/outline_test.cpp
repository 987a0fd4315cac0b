// The outline round the directly visible object against the disc it is defined by, pixel by pixel.
#include <ivis/render/outline.h>
#include <ivis/render/pixel_mapping.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ivis::render {
namespace {

/// The outline by its definition: a direct pixel with a pixel that is not direct, or a position
/// outside the picture, within Euclidean distance @a radius.
bool onOutlineByDisc(const core::Channel& region, int w, int h, int x, int y, int radius)
{
    if (region[std::size_t(y) * w + x] != float(Region::Direct)) return false;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            if (dx * dx + dy * dy > radius * radius) continue;
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h) return true;
            if (region[std::size_t(ny) * w + nx] != float(Region::Direct)) return true;
        }
    return false;
}

/// Random round blobs of direct pixels on background and indirect ones, with single-pixel holes.
core::Channel blobs(int w, int h, std::mt19937& random)
{
    core::Channel region(std::size_t(w) * h, float(Region::Background));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int blob = 0; blob < 6; ++blob) {
        const double cx = unit(random) * w, cy = unit(random) * h, r = 2.0 + unit(random) * 0.4 * std::max(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (std::hypot(x - cx, y - cy) < r) region[std::size_t(y) * w + x] = float(Region::Direct);
    }
    for (std::size_t i = 0; i < region.size(); ++i) {
        const double u = unit(random);
        if (u < 0.01) region[i] = float(Region::Indirect);
        else if (u < 0.02) region[i] = float(Region::Background);
    }
    return region;
}

TEST(Outline, IsTheDirectPixelsWithinTheDiscOfAPixelNotDirect)
{
    std::mt19937 random(7);
    for (const auto& [w, h] : {std::pair{61, 47}, std::pair{5, 90}, std::pair{3, 3}, std::pair{120, 1}})
        for (int radius = 1; radius <= 9; ++radius) {
            const core::Channel region = blobs(w, h, random);
            const std::vector<std::uint8_t> mask = outlineMask(region, w, h, radius);
            std::size_t marked = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const bool expected = onOutlineByDisc(region, w, h, x, y, radius);
                    ASSERT_EQ(expected, mask[std::size_t(y) * w + x] != 0)
                        << w << " x " << h << ", radius " << radius << ", pixel " << x << ", " << y;
                    marked += expected;
                }
            if (w == 61 && radius <= 3) {
                EXPECT_GT(marked, 0u);
            }
        }
}

TEST(Outline, AWholeDirectPictureIsOutlinedOnlyAlongItsBorder)
{
    const int w = 40, h = 30, radius = 3;
    const core::Channel region(std::size_t(w) * h, float(Region::Direct));
    const std::vector<std::uint8_t> mask = outlineMask(region, w, h, radius);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool border = x < radius || y < radius || x >= w - radius || y >= h - radius;
            EXPECT_EQ(border, mask[std::size_t(y) * w + x] != 0) << x << ", " << y;
        }
}

}  // namespace
}  // namespace ivis::render
