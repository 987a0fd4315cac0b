// The hot-spot rule's test of one view (docs/optimisation.md, "The hot-spot rule"): every hot spot
// at least 90% seen, at least 0.9 of it in one region and that region's outline at most 1.6 times
// its hull's; a view failing any one of them, or showing no hot spot, fails.
#include <ivis/optimize/hot_spot_rule.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivis::optimize {
namespace {

HotSpotShape shape(double share, double outline)
{
    HotSpotShape s;
    s.pixels = 100;
    s.largestShare = share;
    s.outlineRatio = outline;
    return s;
}

TEST(HotSpotRule, EveryHotSpotMustBeSeenAndReadAsOnePlace)
{
    const HotSpotShape round = shape(0.98, 1.27), atEdges = shape(0.9, 1.6);
    EXPECT_TRUE(hotSpotsReadAsOnePlace({0.95, 1.0}, {round, round}));
    EXPECT_TRUE(hotSpotsReadAsOnePlace({0.9, 0.9}, {atEdges, atEdges})) << "the limits themselves pass";
    const double below = std::nextafter(0.9, 0.0), above = std::nextafter(1.6, 2.0);
    EXPECT_FALSE(hotSpotsReadAsOnePlace({below, 1.0}, {round, round})) << "one hot spot too little seen";
    EXPECT_FALSE(hotSpotsReadAsOnePlace({1.0, 1.0}, {round, shape(below, 1.27)})) << "one split in two";
    EXPECT_FALSE(hotSpotsReadAsOnePlace({1.0, 1.0}, {shape(0.98, above), round})) << "one a zigzag band";
    EXPECT_FALSE(hotSpotsReadAsOnePlace({}, {})) << "no hot spot";
    EXPECT_FALSE(hotSpotsReadAsOnePlace({1.0, 1.0}, {round})) << "a shape missing";
    EXPECT_FALSE(hotSpotsReadAsOnePlace({std::nan(""), 1.0}, {round, round}));
}

}  // namespace
}  // namespace ivis::optimize
