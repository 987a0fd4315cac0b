#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/image.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ivis::core {
namespace {

constexpr float kOneLevel = 1.0f / 255.0f;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// The map's colour at t, back in sRGB, where published tables live.
glm::vec3 srgbAt(const Colormap& map, float t)
{
    const glm::vec3 c = map.at(t);
    return {srgbFromLinear(c.r), srgbFromLinear(c.g), srgbFromLinear(c.b)};
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance)
{
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

float luminance(const glm::vec3& linear) { return 0.2126f * linear.r + 0.7152f * linear.g + 0.0722f * linear.b; }

TEST(Colormap, ViridisMatchesMatplotlib)
{
    const Colormap& viridis = colormap("viridis");
    expectNear(srgbAt(viridis, 0.0f), {0.267004f, 0.004874f, 0.329415f}, kOneLevel);
    expectNear(srgbAt(viridis, 0.5f), {0.127568f, 0.566949f, 0.550556f}, kOneLevel);
    expectNear(srgbAt(viridis, 1.0f), {0.993248f, 0.906157f, 0.143936f}, kOneLevel);
    expectNear(srgbAt(viridis, 0.25f), {0.229739f, 0.322361f, 0.545706f}, kOneLevel);  // entry 64 of 256
}

TEST(Colormap, ReturnsLinearLight)
{
    const glm::vec3 c = colormap("grey").at(0.5f);
    EXPECT_NEAR(c.r, 0.214041f, 1e-5f);  // sRGB 0.5 decoded
    EXPECT_FLOAT_EQ(c.r, c.g);
    EXPECT_FLOAT_EQ(c.g, c.b);
    EXPECT_EQ(colormap("grey").at(0.0f), glm::vec3(0.0f));
    EXPECT_EQ(colormap("grey").at(1.0f), glm::vec3(1.0f));
}

TEST(Colormap, ClampsOutsideUnitIntervalAndMapsNanLikeZero)
{
    const Colormap& viridis = colormap("viridis");
    EXPECT_EQ(viridis.at(-3.0f), viridis.at(0.0f));
    EXPECT_EQ(viridis.at(7.0f), viridis.at(1.0f));
    EXPECT_EQ(viridis.at(kNaN), viridis.at(0.0f));
    EXPECT_EQ(viridis.at(kInf), viridis.at(1.0f));
}

TEST(Colormap, CoolWarmEndpointsAndWhiteMiddle)
{
    const Colormap& coolWarm = colormap("coolwarm");
    expectNear(srgbAt(coolWarm, 0.0f), {0.230f, 0.299f, 0.754f}, kOneLevel);
    expectNear(srgbAt(coolWarm, 1.0f), {0.706f, 0.016f, 0.150f}, kOneLevel);
    expectNear(srgbAt(coolWarm, 0.5f), {0.865f, 0.865f, 0.865f}, 2.0f * kOneLevel);
    // Moreland's published 8-bit table, entries 8 and 24 of 33.
    expectNear(srgbAt(coolWarm, 0.25f), glm::vec3(141, 176, 254) / 255.0f, 1.5f * kOneLevel);
    expectNear(srgbAt(coolWarm, 0.75f), glm::vec3(244, 154, 123) / 255.0f, 1.5f * kOneLevel);
}

TEST(Colormap, CoolWarmLuminanceRisesToTheMiddleThenFalls)
{
    const Colormap& coolWarm = colormap("coolwarm");
    constexpr int kSteps = 200;
    for (int i = 1; i <= kSteps; ++i) {
        const float t0 = float(i - 1) / kSteps, t1 = float(i) / kSteps;
        const float y0 = luminance(coolWarm.at(t0)), y1 = luminance(coolWarm.at(t1));
        if (t1 <= 0.5f) {
            EXPECT_GT(y1, y0) << "t = " << t1;
        } else if (t0 >= 0.5f) {
            EXPECT_LT(y1, y0) << "t = " << t1;
        }
    }
}

TEST(Colormap, ViridisLuminanceIncreases)
{
    const Colormap& viridis = colormap("viridis");
    for (int i = 1; i <= 100; ++i)
        EXPECT_GT(luminance(viridis.at(i / 100.0f)), luminance(viridis.at((i - 1) / 100.0f))) << i;
}

TEST(Colormap, PublishedTablesMatchTheirSources)
{
    // First, middle (entry 128 of 256 at t = 128/255) and last entries of the published tables.
    expectNear(srgbAt(colormap("magma"), 0.0f), {0.001462f, 0.000466f, 0.013866f}, 1e-5f);
    expectNear(srgbAt(colormap("magma"), 1.0f), {0.987053f, 0.991438f, 0.749504f}, 1e-5f);
    expectNear(srgbAt(colormap("inferno"), 1.0f), {0.988362f, 0.998364f, 0.644924f}, 1e-5f);
    expectNear(srgbAt(colormap("plasma"), 0.0f), {0.050383f, 0.029803f, 0.527975f}, 1e-5f);
    expectNear(srgbAt(colormap("turbo"), 0.0f), {0.18995f, 0.07176f, 0.23217f}, 1e-5f);
    expectNear(srgbAt(colormap("turbo"), 128.0f / 255.0f), {0.64362f, 0.98999f, 0.23356f}, 1e-5f);
    expectNear(srgbAt(colormap("turbo"), 1.0f), {0.47960f, 0.01583f, 0.01055f}, 1e-5f);
    // ColorBrewer RdBu reversed: #053061 ... #f7f7f7 at the middle ... #67001f.
    expectNear(srgbAt(colormap("blue-white-red"), 0.0f), {5 / 255.0f, 48 / 255.0f, 97 / 255.0f}, 1e-5f);
    expectNear(srgbAt(colormap("blue-white-red"), 0.5f), {247 / 255.0f, 247 / 255.0f, 247 / 255.0f}, 1e-5f);
    expectNear(srgbAt(colormap("blue-white-red"), 1.0f), {103 / 255.0f, 0.0f, 31 / 255.0f}, 1e-5f);
}

TEST(Colormap, SequentialTablesGrowInLuminance)
{
    for (const char* name : {"magma", "inferno", "plasma"}) {
        const Colormap& map = colormap(name);
        for (int i = 1; i <= 100; ++i)
            EXPECT_GT(luminance(map.at(i / 100.0f)), luminance(map.at((i - 1) / 100.0f))) << name << " " << i;
    }
}

TEST(Colormap, NamesAndUnknownName)
{
    EXPECT_EQ(colormapNames(), (std::vector<std::string>{"viridis", "coolwarm", "grey", "blue-white-red", "inferno",
                                                         "magma", "plasma", "turbo"}));
    EXPECT_EQ(colormap(kDefaultColormap).name(), "viridis");
    EXPECT_EQ(&colormap("coolwarm"), &colormap("coolwarm"));
    try {
        colormap("jet");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "unknown colour map 'jet' (known: viridis, coolwarm, grey, blue-white-red, inferno, magma, plasma, turbo)");
    }
    EXPECT_THROW(Colormap("one", {glm::vec3(0.0f)}), ValueError);
}

TEST(ScalarRange, NormalizesAndClamps)
{
    const ScalarRange range{2.0f, 6.0f};
    EXPECT_FLOAT_EQ(range.normalized(2.0f), 0.0f);
    EXPECT_FLOAT_EQ(range.normalized(3.0f), 0.25f);
    EXPECT_FLOAT_EQ(range.normalized(6.0f), 1.0f);
    EXPECT_FLOAT_EQ(range.normalized(-100.0f), 0.0f);
    EXPECT_FLOAT_EQ(range.normalized(kInf), 1.0f);
    EXPECT_TRUE(std::isnan(range.normalized(kNaN)));
    EXPECT_FLOAT_EQ((ScalarRange{3.0f, 3.0f}.normalized(-8.0f)), 0.5f);
    const float big = std::numeric_limits<float>::max();
    EXPECT_FLOAT_EQ((ScalarRange{-big, big}.normalized(0.0f)), 0.5f);  // no overflow of hi - lo
}

TEST(ScalarRange, FromDataIgnoresNonFiniteValues)
{
    const ScalarRange range = scalarRangeFromData({kNaN, 4.0f, -kInf, -1.5f, 2.0f, kInf});
    EXPECT_EQ(range.lo, -1.5f);
    EXPECT_EQ(range.hi, 4.0f);
    const ScalarRange none = scalarRangeFromData({kNaN});
    EXPECT_EQ(none.lo, 0.0f);
    EXPECT_EQ(none.hi, 0.0f);
    EXPECT_EQ(scalarRangeFromData({}).hi, 0.0f);
}

TEST(ScalarRange, FromUserValidates)
{
    const ScalarRange range = scalarRangeFromUser(-0.5, 2.0);
    EXPECT_EQ(range.lo, -0.5f);
    EXPECT_EQ(range.hi, 2.0f);
    EXPECT_THROW(scalarRangeFromUser(1.0, 1.0), ValueError);
    EXPECT_THROW(scalarRangeFromUser(2.0, 1.0), ValueError);
    EXPECT_THROW(scalarRangeFromUser(std::nan(""), 1.0), ValueError);
    EXPECT_THROW(scalarRangeFromUser(0.0, std::numeric_limits<double>::infinity()), ValueError);
    EXPECT_THROW(scalarRangeFromUser(0.0, 1e300), ValueError);       // not a float
    EXPECT_THROW(scalarRangeFromUser(1.0, 1.0 + 1e-12), ValueError);  // equal once a float
    try {
        scalarRangeFromUser(3.0, 1.0);
    } catch (const ValueError& e) {
        EXPECT_STREQ(e.what(), "invalid range [3, 1]: lo must be less than hi");
    }
    // Ends apart in double but one float: it printed "invalid range [1, 1]: lo must be less than hi".
    try {
        scalarRangeFromUser(1.0, 1.00000001);
        ADD_FAILURE() << "not refused";
    } catch (const ValueError& e) {
        EXPECT_STREQ(e.what(), "invalid range [1, 1.00000001]: lo and hi are one number in single precision, "
                               "which the colours are mapped in");
    }
}

}  // namespace
}  // namespace ivis::core
