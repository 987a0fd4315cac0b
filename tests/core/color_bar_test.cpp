#include <ivis/core/color_bar.h>
#include <ivis/core/errors.h>
#include <ivis/core/font.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <set>
#include <vector>

namespace ivis::core {
namespace {

const glm::vec4 kBackground(0.3f, 0.05f, 0.2f, 1.0f);

std::vector<std::string> labels(const std::vector<ColorBarTick>& ticks)
{
    std::vector<std::string> out;
    for (const ColorBarTick& t : ticks) out.push_back(t.label);
    return out;
}

/// True when @a step is 1, 2 or 5 times a power of ten.
bool isRoundStep(double step)
{
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    return std::abs(mantissa - 1.0) < 1e-6 || std::abs(mantissa - 2.0) < 1e-6 || std::abs(mantissa - 5.0) < 1e-6;
}

TEST(ColorBarTicks, LinearTicksAreRoundMultiplesBetweenTheMarkedEnds)
{
    for (const ScalarRange range : {ScalarRange{0.0931f, 1234.5f}, ScalarRange{-2.0f, 2.0f}, ScalarRange{1000.1f, 1000.3f},
                                    ScalarRange{0.0f, 1.0f}, ScalarRange{-37.0f, 0.4f}, ScalarRange{3e-5f, 7e-5f}}) {
        const std::vector<ColorBarTick> ticks = colorBarTicks({range, false, false});
        ASSERT_GE(ticks.size(), 5u) << range.lo << " " << range.hi;
        EXPECT_TRUE(ticks.front().rangeEnd);
        EXPECT_TRUE(ticks.back().rangeEnd);
        // Ends within float rounding of the range (the scale's ends are floats).
        const double magnitude = std::max({std::abs(range.lo), std::abs(range.hi), range.hi - range.lo});
        EXPECT_NEAR(ticks.front().value, range.lo, 1e-6 * magnitude);
        EXPECT_NEAR(ticks.back().value, range.hi, 1e-6 * magnitude);
        std::vector<double> interior;
        for (const ColorBarTick& t : ticks)
            if (!t.rangeEnd) interior.push_back(t.value);
        ASSERT_GE(interior.size(), 3u);
        const double step = interior[1] - interior[0];
        EXPECT_TRUE(isRoundStep(step)) << step;
        for (std::size_t i = 1; i < interior.size(); ++i) EXPECT_NEAR(interior[i] - interior[i - 1], step, 1e-6 * step);
        for (const ColorBarTick& t : ticks) EXPECT_NEAR(t.position, (t.value - range.lo) / (range.hi - range.lo), 1e-5 + 1.2e-7 * magnitude / (range.hi - range.lo))
                << t.label;
        const std::vector<std::string> text = labels(ticks);
        EXPECT_EQ(std::set<std::string>(text.begin(), text.end()).size(), text.size()) << ::testing::PrintToString(text);
    }
    EXPECT_EQ(labels(colorBarTicks({{-2.0f, 2.0f}, false, false})),
              (std::vector<std::string>{"−2", "−1", "0", "1", "2"}));
    EXPECT_EQ(labels(colorBarTicks({{0.0f, 1.0f}, false, false})),
              (std::vector<std::string>{"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"}));
}

TEST(ColorBarTicks, LargeAndSmallMagnitudesUsePowersOfTen)
{
    const std::vector<std::string> big = labels(colorBarTicks({{0.0f, 200000.0f}, false, false}));
    EXPECT_EQ(big[1], "5×10⁴");
    EXPECT_EQ(big.back(), "2×10⁵");
    const std::vector<std::string> small = labels(colorBarTicks({{0.0f, 4e-4f}, false, false}));
    EXPECT_EQ(small[1], "10⁻⁴");
}

TEST(ColorBarTicks, LogTicksArePowersOfTenThenTheirMultiples)
{
    EXPECT_EQ(labels(colorBarTicks({{0.01f, 1000.0f}, true, false})),
              (std::vector<std::string>{"0.01", "0.1", "1", "10", "100", "1000"}));
    EXPECT_EQ(labels(colorBarTicks({{1.0f, 30.0f}, true, false})),
              (std::vector<std::string>{"1", "2", "5", "10", "20", "30"}));
    const std::vector<ColorBarTick> wide = colorBarTicks({{1e-9f, 1e-3f}, true, false});
    EXPECT_EQ(wide.front().label, "10⁻⁹");
    EXPECT_NEAR(wide[1].position, 1.0 / 6.0, 1e-5);
}

TEST(ColorBarTicks, InvertedScalesPutTheHighEndAtTheBottom)
{
    const std::vector<ColorBarTick> ticks = colorBarTicks({{0.0f, 10.0f}, false, true});
    EXPECT_FLOAT_EQ(ticks.front().position, 1.0f);
    EXPECT_FLOAT_EQ(ticks.back().position, 0.0f);
}

TEST(ColorBarTicks, AnEmptyRangeHasOneLabel)
{
    EXPECT_EQ(labels(colorBarTicks({{4.5f, 4.5f}, false, false})), std::vector<std::string>{"4.5"});
}

class ColorBarMargin : public ::testing::TestWithParam<std::tuple<int, int, LegendSide>> {};

TEST_P(ColorBarMargin, GrowsTheCanvasAndLeavesThePictureUntouched)
{
    const auto [width, height, side] = GetParam();
    Image picture(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) picture.at(x, y) = glm::vec4(float(x % 7) / 7.0f, float(y % 5) / 5.0f, 0.5f, 1.0f);
    const ColorBarContent content{"viridis", {{0.0931f, 1234.5f}, false, false}, "wall shear stress", "dyn/cm²"};
    const Image canvas = withColorBar(picture, content, side, kBackground);
    const ColorBarDrawing d = layOutColorBar(content, width, height, side);

    const bool bottom = side == LegendSide::Bottom;
    EXPECT_EQ(canvas.width(), width + (bottom ? 0 : d.width));
    EXPECT_EQ(canvas.height(), bottom ? height + d.height : std::max(height, d.height));
    const int px = side == LegendSide::Left ? d.width : 0, py = bottom ? 0 : (canvas.height() - height) / 2;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) ASSERT_EQ(canvas.at(px + x, py + y), picture.at(x, y)) << x << ", " << y;

    // The margin holds dark ink (text, ticks, frame) and the ramp from the map's low to high end.
    const int bx = side == LegendSide::Right ? width : 0, by = bottom ? height : 0;
    int ink = 0;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const glm::vec4& p = canvas.at(bx + x, by + y);
            if (p.r < 0.05f && p.g < 0.05f && p.b < 0.05f && !d.gradient.contains(x, y)) ++ink;
        }
    EXPECT_GT(ink, 200);
    const Colormap& map = colormap("viridis");
    const PixelRect& g = d.gradient;
    const glm::vec3 low(d.vertical ? canvas.at(bx + (g.x0 + g.x1) / 2, by + g.y1 - 1) : canvas.at(bx + g.x0, by + (g.y0 + g.y1) / 2));
    const glm::vec3 high(d.vertical ? canvas.at(bx + (g.x0 + g.x1) / 2, by + g.y0) : canvas.at(bx + g.x1 - 1, by + (g.y0 + g.y1) / 2));
    EXPECT_LT(glm::distance(low, map.at(0.0f)), 0.02f);
    EXPECT_LT(glm::distance(high, map.at(1.0f)), 0.02f);
    // Readable text: at least 12 pixels, growing with the picture.
    EXPECT_GE(d.fontPixels, 12);
    EXPECT_GE(d.fontPixels, (bottom ? width : height) / 50);
    EXPECT_GE(d.ticks.size(), 5u);
}

INSTANTIATE_TEST_SUITE_P(SizesAndSides, ColorBarMargin,
                         ::testing::Values(std::tuple{500, 500, LegendSide::Right}, std::tuple{640, 480, LegendSide::Left},
                                           std::tuple{1000, 1000, LegendSide::Bottom},
                                           std::tuple{4000, 3000, LegendSide::Right}));

TEST(ColorBar, KeptTickLabelsDoNotOverlap)
{
    for (const LegendSide side : {LegendSide::Right, LegendSide::Bottom}) {
        // Beside a vertical bar the title's lines count too: the top tick's label stands above the bar.
        const bool vertical = side == LegendSide::Right;
        const ColorBarContent content{"viridis", {{1e-9f, 1e3f}, true, false}, vertical ? "pressure" : "",
                                      vertical ? "Pa" : ""};
        const ColorBarDrawing d = layOutColorBar(content, 500, 500, side);
        std::vector<std::pair<int, int>> spans;  // along the bar
        for (const ColorBarDrawing::Text& t : d.labels) {
            const TextExtent e = Font::standard().measure(t.text, d.fontPixels);
            spans.push_back(side == LegendSide::Right ? std::pair{t.baseline - e.ascent, t.baseline + e.descent}
                                                      : std::pair{t.x - e.width / 2, t.x + e.width / 2});
        }
        std::sort(spans.begin(), spans.end());
        for (std::size_t i = 1; i < spans.size(); ++i) EXPECT_LE(spans[i - 1].second, spans[i].first + 2);
        EXPECT_TRUE(std::any_of(d.ticks.begin(), d.ticks.end(), [](const ColorBarTick& t) { return t.label == "10⁻⁹"; }));
        EXPECT_TRUE(std::any_of(d.ticks.begin(), d.ticks.end(), [](const ColorBarTick& t) { return t.label == "1000"; }));
    }
}

TEST(ColorBar, LongTitlesAndUnitsWrapWithinTheBarsWidth)
{
    const std::string title = "wall shear stress magnitude averaged over the cardiac cycle at peak systole, "
                              "normalised by its average over the whole aneurysm sac and the parent artery";
    const std::string units(500, 'x');  // one word wider than any bar
    const std::string ellipsis = "\xE2\x80\xA6";
    const ColorBarContent plain{"viridis", {{0.0f, 5.0f}, false, false}, "p", "Pa"};
    for (const LegendSide side : {LegendSide::Right, LegendSide::Bottom}) {
        const ColorBarContent content{"viridis", {{0.0f, 5.0f}, false, false}, title, units};
        const ColorBarDrawing d = layOutColorBar(content, 1000, 1000, side);
        const ColorBarDrawing p = layOutColorBar(plain, 1000, 1000, side);
        const int limit = side == LegendSide::Bottom ? d.gradient.x1 - d.gradient.x0 : std::max(p.width, 1000 / 4);
        std::vector<std::string> lines;  // the title's, not the ticks'
        for (const ColorBarDrawing::Text& t : d.labels) {
            EXPECT_LE(Font::standard().measure(t.text, d.fontPixels).width, limit) << t.text;
            if (std::none_of(d.ticks.begin(), d.ticks.end(), [&](const ColorBarTick& k) { return k.label == t.text; }))
                lines.push_back(t.text);
        }
        if (side == LegendSide::Right) {
            EXPECT_LE(d.width, limit + 2 * d.fontPixels);
        }
        // Two lines of the title, broken between its words, then two of the units, cut within the
        // one word and at the end, each part's second line ending in an ellipsis.
        ASSERT_EQ(lines.size(), 4u);
        EXPECT_EQ(title.rfind(lines[0] + " ", 0), 0u);
        EXPECT_EQ(lines[1].substr(lines[1].size() - 3), ellipsis);
        EXPECT_EQ(title.find(lines[1].substr(0, lines[1].size() - 3), lines[0].size() + 1), lines[0].size() + 1);
        EXPECT_EQ(lines[2], "[" + std::string(lines[2].size() - 1, 'x'));
        EXPECT_EQ(lines[3], std::string(lines[3].size() - 3, 'x') + ellipsis);
    }
}

TEST(ColorBar, SvgHasTheRampAndEveryLabel)
{
    const ColorBarContent content{"inferno", {{0.0f, 5.0f}, false, false}, "p & q", "dyn/cm²"};
    const std::string svg = colorBarSvg(content, 800, 600, LegendSide::Right);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("<linearGradient"), std::string::npos);
    EXPECT_NE(svg.find("p &amp; q [dyn/cm²]"), std::string::npos);
    for (const ColorBarTick& t : layOutColorBar(content, 800, 600, LegendSide::Right).ticks)
        EXPECT_NE(svg.find(">" + t.label + "<"), std::string::npos) << t.label;
    EXPECT_EQ(svg.find("</svg>"), svg.size() - 7);
    // A Latin-1 name and units that are not UTF-8, and a control byte: U+FFFD, so the SVG stays XML.
    const ColorBarContent latin1{"inferno", {{0.0f, 5.0f}, false, false}, "pr\xe9ssion", "\xff\x01Pa"};
    const std::string replaced = colorBarSvg(latin1, 800, 600, LegendSide::Right);
    EXPECT_NE(replaced.find("pr\xEF\xBF\xBDssion [\xEF\xBF\xBD\xEF\xBF\xBDPa]"), std::string::npos);
}

TEST(ColorBar, RejectsAnUnknownSide)
{
    EXPECT_EQ(legendSideFromName("bottom"), LegendSide::Bottom);
    EXPECT_THROW(legendSideFromName("top"), InputError);
}

}  // namespace
}  // namespace ivis::core
