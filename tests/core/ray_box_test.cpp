// rayBoxInterval: entry and exit through faces, an origin inside, misses beside and behind,
// rays parallel to a slab, and a ray that only grazes an edge.
#include <ivis/core/ray_box.h>

#include <gtest/gtest.h>

namespace ivis::core {
namespace {

const Bounds3 kBox{glm::dvec3(-1.0, -2.0, -3.0), glm::dvec3(1.0, 2.0, 3.0)};

TEST(RayBoxInterval, EntersAndExitsThroughTheFacesItCrosses)
{
    float tEnter = -1.0f, tExit = -1.0f;
    ASSERT_TRUE(rayBoxInterval({-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FLOAT_EQ(tEnter, 4.0f);
    EXPECT_FLOAT_EQ(tExit, 6.0f);
    // Diagonal: enters through x = -1 at t = 2 (y = -1), leaves through x = 1 at t = 4 (y = 1).
    ASSERT_TRUE(rayBoxInterval({-3.0f, -3.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FLOAT_EQ(tEnter, 2.0f);
    EXPECT_FLOAT_EQ(tExit, 4.0f);
}

TEST(RayBoxInterval, StartsAtZeroFromInside)
{
    float tEnter, tExit;
    ASSERT_TRUE(rayBoxInterval({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f}, kBox, tEnter, tExit));
    EXPECT_EQ(tEnter, 0.0f);
    EXPECT_FLOAT_EQ(tExit, 1.5f);
}

TEST(RayBoxInterval, MissesBesideAndBehind)
{
    float tEnter, tExit;
    EXPECT_FALSE(rayBoxInterval({-5.0f, 3.0f, 0.0f}, {1.0f, 0.1f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FALSE(rayBoxInterval({5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, kBox, tEnter, tExit)) << "box behind";
}

TEST(RayBoxInterval, ParallelRaysHitOnlyInsideTheirSlab)
{
    float tEnter, tExit;
    EXPECT_TRUE(rayBoxInterval({0.5f, -5.0f, 2.9f}, {0.0f, 1.0f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FLOAT_EQ(tEnter, 3.0f);
    EXPECT_FLOAT_EQ(tExit, 7.0f);
    EXPECT_FALSE(rayBoxInterval({1.5f, -5.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FALSE(rayBoxInterval({0.0f, -5.0f, 0.0f}, {1e-13f, 1.0f, 0.0f}, {glm::dvec3(0.5, -1, -1), glm::dvec3(1, 1, 1)},
                                tEnter, tExit))
        << "a component below 1e-12 counts as parallel";
}

TEST(RayBoxInterval, AGrazingRayHasAnEmptyInterval)
{
    float tEnter, tExit;
    // Through the corner (1, 2) of the x-y section only: tEnter == tExit.
    EXPECT_FALSE(rayBoxInterval({0.0f, 3.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, kBox, tEnter, tExit));
    EXPECT_FLOAT_EQ(tEnter, 1.0f);
    EXPECT_FLOAT_EQ(tExit, 1.0f);
}

}  // namespace
}  // namespace ivis::core
