#include <ivis/core/data_array.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ivis::core {
namespace {

TEST(DataArray, ComponentsMagnitudeAndRange)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const DataArray v{"v", Association::Point, ValueType::Float32, 2, {3, -4, nan, 1, -6, 8, 0, 0}};
    EXPECT_EQ(v.tuples(), 4u);
    EXPECT_EQ(v.defaultComponent(), kMagnitude);
    EXPECT_EQ(v.at(0, 1), -4.0);
    EXPECT_EQ(v.at(0, kMagnitude), 5.0);
    EXPECT_TRUE(std::isnan(v.at(1, kMagnitude)));
    EXPECT_EQ(finiteRange(v, kMagnitude), std::make_pair(0.0, 10.0));
    EXPECT_EQ(finiteRange(v, 0), std::make_pair(-6.0, 3.0));

    const DataArray s{"s", Association::Cell, ValueType::Int8, 1, {-2, 7}};
    EXPECT_EQ(s.defaultComponent(), 0);
    EXPECT_EQ(s.at(0, kMagnitude), 2.0);  // the length of a one-component tuple
    EXPECT_EQ(finiteRange(s, s.defaultComponent()), std::make_pair(-2.0, 7.0));
    // No finite value: NaN, which `info` prints as such (0 to 0 would read as a constant array).
    const auto [lo, hi] = finiteRange(DataArray{}, 0);
    EXPECT_TRUE(std::isnan(lo) && std::isnan(hi));
    const DataArray allNan{"n", Association::Point, ValueType::Float32, 1, {nan, nan}};
    EXPECT_TRUE(std::isnan(finiteRange(allNan, 0).first));
    EXPECT_TRUE(std::isnan(finiteRange(allNan, 0).second));
}

TEST(DataArray, TypeNamesAndSizes)
{
    EXPECT_STREQ(valueTypeName(ValueType::UInt16), "UInt16");
    EXPECT_STREQ(valueTypeName(ValueType::Float64), "Float64");
    EXPECT_EQ(valueTypeSize(ValueType::Int8), 1u);
    EXPECT_EQ(valueTypeSize(ValueType::UInt64), 8u);
    EXPECT_EQ(valueTypeSize(ValueType::Float32), 4u);
    EXPECT_STREQ(associationName(Association::Cell), "cell");
}

}  // namespace
}  // namespace ivis::core
