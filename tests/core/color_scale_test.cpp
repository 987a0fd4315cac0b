#include <ivis/core/color_scale.h>
#include <ivis/core/errors.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ivis::core {
namespace {

TEST(ColorScale, PositionsAreLinearLogarithmicOrInverted)
{
    ColorScale linear{{-2.0f, 6.0f}, false, false};
    EXPECT_FLOAT_EQ(linear.position(2.0f), 0.5f);
    EXPECT_FLOAT_EQ(linear.position(-10.0f), 0.0f);
    EXPECT_FLOAT_EQ(linear.position(10.0f), 1.0f);
    EXPECT_TRUE(std::isnan(linear.position(std::numeric_limits<float>::quiet_NaN())));

    ColorScale log{{0.01f, 100.0f}, true, false};
    EXPECT_NEAR(log.position(1.0f), 0.5f, 1e-6f);  // the geometric middle
    EXPECT_NEAR(log.position(0.1f), 0.25f, 1e-6f);
    EXPECT_FLOAT_EQ(log.position(-3.0f), 0.0f);   // not positive: the low end
    EXPECT_FLOAT_EQ(log.position(1e6f), 1.0f);

    ColorScale inverted = log;
    inverted.invert = true;
    EXPECT_NEAR(inverted.position(0.1f), 0.75f, 1e-6f);
    for (const ColorScale& scale : {linear, log, inverted})
        for (const double t : {0.0, 0.3, 0.5, 0.9, 1.0})
            EXPECT_NEAR(scale.position(float(scale.valueAt(t))), t, 1e-5) << t;
}

TEST(Percentile, InterpolatesBetweenOrderStatisticsLikeNumPy)
{
    EXPECT_DOUBLE_EQ(percentile({4.0f, 1.0f, 3.0f, 2.0f}, 50.0), 2.5);
    EXPECT_DOUBLE_EQ(percentile({4.0f, 1.0f, 3.0f, 2.0f}, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(percentile({4.0f, 1.0f, 3.0f, 2.0f}, 100.0), 4.0);
    EXPECT_NEAR(percentile({10.0f, 20.0f, 30.0f, 40.0f, 50.0f}, 90.0), 46.0, 1e-9);
    EXPECT_DOUBLE_EQ(percentile({std::nanf(""), 7.0f}, 30.0), 7.0);
    EXPECT_TRUE(std::isnan(percentile({}, 50.0)));

    // Against sorting: the k-th of n values sits at percentile 100 k / (n - 1).
    std::mt19937 rng(7);
    std::lognormal_distribution<float> heavy(0.0f, 2.0f);
    std::vector<float> values(1001);
    for (float& v : values) v = heavy(rng);
    std::vector<float> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    for (const int k : {0, 10, 500, 990, 1000}) EXPECT_DOUBLE_EQ(percentile(values, k / 10.0), sorted[std::size_t(k)]);
}

TEST(ColorScaleRequest, ResolvesTheRangeFromTheData)
{
    const std::vector<float> values = {-4.0f, -1.0f, 0.0f, 0.5f, 2.0f, 3.0f, std::nanf("")};
    ColorScaleRequest request;
    EXPECT_EQ(request.resolve(values).range.lo, -4.0f);
    EXPECT_EQ(request.resolve(values).range.hi, 3.0f);

    request.symmetric = true;
    EXPECT_EQ(request.resolve(values).range.lo, -4.0f);
    EXPECT_EQ(request.resolve(values).range.hi, 4.0f);

    request = {};
    request.log = true;  // the smallest positive value is the low end
    EXPECT_EQ(request.resolve(values).range.lo, 0.5f);
    EXPECT_EQ(request.resolve(values).range.hi, 3.0f);
    EXPECT_TRUE(request.resolve(values).log);

    request = {};
    request.percentiles = std::pair{0.0, 50.0};
    EXPECT_EQ(request.resolve(values).range.lo, -4.0f);
    EXPECT_EQ(request.resolve(values).range.hi, 0.25f);

    request = {};
    request.range = ScalarRange{1.0f, 2.0f};
    request.invert = true;
    EXPECT_EQ(request.resolve(values).range.lo, 1.0f);
    EXPECT_TRUE(request.resolve(values).invert);
}

TEST(ColorScaleRequest, RejectsContradictions)
{
    ColorScaleRequest request;
    request.log = true;
    request.symmetric = true;
    EXPECT_THROW(request.validate(), ValueError);

    request = {};
    request.range = ScalarRange{0.0f, 1.0f};
    request.percentiles = std::pair{1.0, 99.0};
    EXPECT_THROW(request.validate(), ValueError);

    request = {};
    request.percentiles = std::pair{50.0, 20.0};
    EXPECT_THROW(request.validate(), ValueError);
    request.percentiles = std::pair{-1.0, 20.0};
    EXPECT_THROW(request.validate(), ValueError);

    request = {};
    request.log = true;
    request.range = ScalarRange{0.0f, 1.0f};
    EXPECT_THROW(request.validate(), ValueError);

    request = {};
    request.log = true;
    EXPECT_THROW(request.resolve({-3.0f, -1.0f, 0.0f}), ValueError);
    try {  // the data's problem names its file, as every other one does
        request.resolve({-3.0f, -1.0f, 0.0f}, "strip.vtk");
        ADD_FAILURE() << "not refused";
    } catch (const ValueError& e) {
        EXPECT_STREQ(e.what(), "strip.vtk: --log: the scalar has no positive value to put on a logarithmic scale");
    }
}

}  // namespace
}  // namespace ivis::core
