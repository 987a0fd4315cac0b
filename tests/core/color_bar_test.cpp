#include <ivis/core/color_bar.h>
#include <ivis/core/errors.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <string>
#include <utility>
#include <vector>

namespace ivis::core {
namespace {

const glm::vec4 kBackground(0.3f, 0.05f, 0.2f, 1.0f);

TEST(ColorBar, LabelsAreCompactAndDistinct)
{
    EXPECT_EQ(colorBarLabels({0.0f, 1200.0f}), (std::vector<std::string>{"0", "600", "1.2e+03"}));
    EXPECT_EQ(colorBarLabels({0.0931f, 0.25f})[0], "0.0931");
    EXPECT_EQ(colorBarLabels({-2.0f, 2.0f}), (std::vector<std::string>{"-2", "0", "2"}));
    EXPECT_EQ(colorBarLabels({1000.1f, 1000.3f}), (std::vector<std::string>{"1000.1", "1000.2", "1000.3"}));
    EXPECT_EQ(colorBarLabels({4.5f, 4.5f}), std::vector<std::string>{"4.5"});
}

class ColorBarSize : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(ColorBarSize, ChangesPixelsOnlyInItsRegionAtTheRight)
{
    const auto [width, height] = GetParam();
    Image image(width, height, kBackground);
    const Colormap& map = colormap("viridis");
    const ColorBarLayout layout = drawColorBar(image, map, {0.0931f, 1234.5f}, "wss", "Pa");

    const PixelRect& b = layout.backing;
    EXPECT_GE(b.x0, width * 2 / 5);  // tiny images need room for the labels
    EXPECT_LT(b.x1, width);
    EXPECT_GT(b.y0, 0);
    EXPECT_LT(b.y1, height);
    int changed = 0, ink = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec4& p = image.at(x, y);
            if (p == kBackground) continue;
            ++changed;
            ASSERT_TRUE(b.contains(x, y)) << "pixel (" << x << ", " << y << ") changed outside the legend";
            if (p.g < 0.05f && !layout.gradient.contains(x, y)) ++ink;
        }
    EXPECT_GT(changed, (b.x1 - b.x0) * (b.y1 - b.y0) * 9 / 10);  // the backing covers its rectangle
    EXPECT_GT(ink, 50);                                           // dark text, ticks and frame

    // The gradient is the default fraction of the image high, hi at the top, lo at the bottom.
    const PixelRect& g = layout.gradient;
    EXPECT_NEAR(g.y1 - g.y0, ColorBarOptions{}.heightFraction * height, height / 20 + 4);
    EXPECT_GE(g.x1 - g.x0, 6);
    const int x = (g.x0 + g.x1) / 2;
    const float twoRows = 2.0f / float(g.y1 - g.y0);  // colour change over two rows bounds the error
    auto near = [&](int y, float t) {
        const float tolerance = glm::distance(map.at(t), map.at(t > 0.5f ? t - twoRows : t + twoRows));
        return glm::distance(glm::vec3(image.at(x, y)), map.at(t)) < tolerance;
    };
    EXPECT_TRUE(near(g.y0, 1.0f));
    EXPECT_TRUE(near(g.y1 - 1, 0.0f));
    EXPECT_TRUE(near((g.y0 + g.y1) / 2, 0.5f));
}

INSTANTIATE_TEST_SUITE_P(Sizes, ColorBarSize,
                         ::testing::Values(std::pair{128, 128}, std::pair{640, 480}, std::pair{1920, 1080},
                                           std::pair{4000, 3000}));

TEST(ColorBar, BackingMakesTransparentPixelsOpaque)
{
    Image image(300, 200, glm::vec4(0.0f));
    const ColorBarLayout layout = drawColorBar(image, colormap("coolwarm"), {-1.0f, 1.0f}, "", "");
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ASSERT_EQ(image.at(x, y).a, layout.backing.contains(x, y) ? 1.0f : 0.0f) << x << ", " << y;
}

TEST(ColorBar, TitleWidensTheBackingOrWraps)
{
    Image image(640, 480, kBackground);
    const PixelRect plain = drawColorBar(image, colormap("grey"), {0.0f, 1.0f}, "", "").backing;
    const PixelRect titled =
        drawColorBar(image, colormap("grey"), {0.0f, 1.0f}, "wall shear stress magnitude", "Pa").backing;
    EXPECT_LT(titled.x0, plain.x0);
    EXPECT_LT(titled.y0, plain.y0);
}

TEST(ColorBar, RejectsBadOptions)
{
    Image image(64, 64);
    ColorBarOptions options;
    options.heightFraction = 0.0f;
    EXPECT_THROW(drawColorBar(image, colormap("grey"), {0.0f, 1.0f}, "", "", options), ValueError);
    options = {};
    options.backingOpacity = 1.5f;
    EXPECT_THROW(drawColorBar(image, colormap("grey"), {0.0f, 1.0f}, "", "", options), ValueError);
    options = {};
    options.textScale = -1;
    EXPECT_THROW(drawColorBar(image, colormap("grey"), {0.0f, 1.0f}, "", "", options), ValueError);
}

}  // namespace
}  // namespace ivis::core
