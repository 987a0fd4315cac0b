// The hot-spot rule's test of one view (docs/optimisation.md, "The hot-spot rule"): every hot spot
// at least 90% seen, at least 0.9 of it in one region and that region's outline at most 1.6 times
// its hull's; a view failing any one of them, or showing no hot spot, fails. Which way each hot
// spot faces, and the views that put one in the middle of the far side, which the rule skips.
#include <ivis/optimize/hot_spot_rule.h>

#include <ivis/core/hot_spots.h>
#include <ivis/core/procedural_scenes.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
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

/// A camera at distance 3 from the origin along @a direction, looking at the origin.
core::Camera cameraFrom(const glm::dvec3& direction)
{
    core::Camera camera;
    camera.eye = 3.0 * glm::normalize(direction);
    camera.up = std::abs(glm::normalize(direction).y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    return camera;
}

// On the unit sphere each of the two opposite hot spots is a cap: by symmetry its mean normal
// points out through its centre. Seen from beside one spot, the other lies in the middle of the far
// side (facing straight away); seen from the side of their axis, neither does.
TEST(HotSpotRule, AFarSideHotSpotFacesAwayFromTheEye)
{
    core::SurfaceField sphere = core::makeSphere(4);
    const core::HotSpots spots = core::placeHotSpots(sphere.mesh, 2);
    sphere.values = core::hotSpotValues(sphere.mesh, spots);
    const RevealMeasure reveal(sphere, {0.0f, 1.0f});
    ASSERT_EQ(reveal.regionCount(), 2u);
    const std::vector<HotSpotFacing> facings = hotSpotFacings(sphere.mesh, reveal);
    ASSERT_EQ(facings.size(), 2u);
    for (const HotSpotFacing& facing : facings) {
        ASSERT_NEAR(glm::length(facing.normal), 1.0, 1e-9);
        const glm::dvec3 outward = glm::normalize(facing.centroid);
        EXPECT_GT(glm::dot(facing.normal, outward), std::cos(glm::radians(1.0))) << "the cap's normal through its centre";
        const double toSpots = std::max(glm::dot(outward, glm::normalize(glm::dvec3(spots.centres[0]))),
                                        glm::dot(outward, glm::normalize(glm::dvec3(spots.centres[1]))));
        EXPECT_GT(toSpots, std::cos(glm::radians(1.0))) << "each region is one of the placed spots";
    }
    const glm::dvec3 axis = glm::normalize(facings[0].centroid - facings[1].centroid);
    EXPECT_TRUE(someHotSpotFacesAway(facings, cameraFrom(axis))) << "spot 1 on the far side's middle";
    EXPECT_TRUE(someHotSpotFacesAway(facings, cameraFrom(-axis))) << "spot 0 on the far side's middle";
    const glm::dvec3 side = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    EXPECT_FALSE(someHotSpotFacesAway(facings, cameraFrom(side))) << "both on the silhouette";
    // Turned from the side towards spot 0 by 30 degrees: seen from the eye, spot 1 faces about 47
    // degrees from straight away (its direction from a finite distance tilts further than the view).
    EXPECT_TRUE(someHotSpotFacesAway(facings, cameraFrom(std::cos(glm::radians(30.0)) * side +
                                                         std::sin(glm::radians(30.0)) * axis)));
}

// A hot spot girdling the sphere (a band round its equator) faces no one way: never on the far side.
TEST(HotSpotRule, AHotSpotRoundThePartFacesNoOneWay)
{
    core::SurfaceField sphere = core::makeSphere(4);
    sphere.values.clear();
    for (const glm::vec3& p : sphere.mesh.positions) sphere.values.push_back(std::abs(p.y) < 0.3f ? 1.0f : 0.0f);
    const RevealMeasure reveal(sphere, {0.0f, 1.0f});
    ASSERT_EQ(reveal.regionCount(), 1u);
    const std::vector<HotSpotFacing> facings = hotSpotFacings(sphere.mesh, reveal);
    ASSERT_EQ(facings.size(), 1u);
    EXPECT_EQ(facings[0].normal, glm::dvec3(0.0));
    EXPECT_NEAR(glm::length(facings[0].centroid), 0.0, 0.05) << "its centre inside the part";
    EXPECT_FALSE(someHotSpotFacesAway(facings, cameraFrom({0.0, 0.0, 1.0})));
}

}  // namespace
}  // namespace ivis::optimize
