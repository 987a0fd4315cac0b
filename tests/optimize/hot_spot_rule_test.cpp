// The hot-spot rule's test of one view (docs/optimisation.md, "The hot-spot rule"): every hot spot
// at least 90% seen, at least 0.9 of it in one region and that region's outline at most 1.6 times
// its hull's; a view failing any one of them, or showing no hot spot, fails. Which way each hot
// spot faces, the views that put one in the middle of the far side, which the rule skips, and the
// views that show every hot spot side-on, which it tries where none of the search's views reads;
// a picture judged whole (hotSpotsReadIn), as the readable rule asks where the rule chose the view;
// how far a view is from reading (hotSpotShortfall), by which the rule takes the nearest where none
// reads; and the views it tries round that nearest one first (viewsRoundTheNearest).
#include "render/scene_fixture.h"

#include <ivis/optimize/hot_spot_rule.h>

#include <ivis/core/hot_spots.h>
#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
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

TEST(HotSpotRule, TheShortfallIsTheWorstBoundMissedRelativeToItAndZeroExactlyWhereTheHotSpotsRead)
{
    const HotSpotShape round = shape(0.98, 1.27);
    EXPECT_EQ(hotSpotShortfall({0.95, 1.0}, {round, round}), 0.0);
    EXPECT_EQ(hotSpotShortfall({0.9, 0.9}, {shape(0.9, 1.6), shape(0.9, 1.6)}), 0.0) << "the limits themselves";
    EXPECT_NEAR(hotSpotShortfall({0.45, 1.0}, {round, round}), 0.5, 1e-12) << "half the seen share missing";
    EXPECT_NEAR(hotSpotShortfall({1.0, 1.0}, {round, shape(0.72, 1.27)}), 0.2, 1e-12) << "a fifth of the share";
    EXPECT_NEAR(hotSpotShortfall({1.0, 1.0}, {shape(0.98, 2.4), round}), 0.5, 1e-12) << "an outline half again";
    EXPECT_NEAR(hotSpotShortfall({0.81, 1.0}, {shape(0.45, 2.0), shape(0.98, 2.4)}), 0.5, 1e-12) << "the worst of all";
    EXPECT_NEAR(hotSpotShortfall({1.0}, {shape(0.0, 0.0)}), 1.0, 1e-12) << "a hot spot no pixel shows";
    EXPECT_EQ(hotSpotShortfall({}, {}), 1.0);
    EXPECT_EQ(hotSpotShortfall({1.0, 1.0}, {round}), 1.0);
    EXPECT_EQ(hotSpotShortfall({std::nan(""), 1.0}, {round, round}), 1.0);
    EXPECT_EQ(hotSpotShortfall({1.0}, {shape(0.98, std::nan(""))}), 1.0);
    // Zero exactly where the views read, over a grid of values round the limits.
    for (const double seen : {0.5, std::nextafter(0.9, 0.0), 0.9, 1.0})
        for (const double share : {0.2, std::nextafter(0.9, 0.0), 0.9, 1.0})
            for (const double outline : {1.0, 1.6, std::nextafter(1.6, 2.0), 3.0}) {
                const std::vector<double> seens = {1.0, seen};
                const std::vector<HotSpotShape> shapes = {round, shape(share, outline)};
                EXPECT_EQ(hotSpotShortfall(seens, shapes) == 0.0, hotSpotsReadAsOnePlace(seens, shapes))
                    << seen << " " << share << " " << outline;
                EXPECT_GE(hotSpotShortfall(seens, shapes), 0.0);
            }
}

TEST(HotSpotRule, OfTwoRoundsTheOneThatReadsOrComesNearerIsTakenAndBothJudgedCount)
{
    HotSpotChoice none, near, nearer, reads;
    none.judged = 2;
    near.judged = 3, near.chosen = 4, near.shortfall = 0.2;
    nearer.judged = 5, nearer.chosen = 9, nearer.shortfall = 0.1;
    reads.judged = 1, reads.chosen = 7, reads.shortfall = 0.0, reads.reads = true;
    EXPECT_EQ(betterHotSpotChoice(near, nearer).chosen, std::optional<std::size_t>(9));
    EXPECT_EQ(betterHotSpotChoice(nearer, near).chosen, std::optional<std::size_t>(9));
    EXPECT_EQ(betterHotSpotChoice(near, near).chosen, std::optional<std::size_t>(4)) << "a tie keeps the first round's";
    EXPECT_TRUE(betterHotSpotChoice(nearer, reads).reads);
    EXPECT_EQ(betterHotSpotChoice(none, near).chosen, std::optional<std::size_t>(4));
    EXPECT_EQ(betterHotSpotChoice(near, none).chosen, std::optional<std::size_t>(4));
    EXPECT_FALSE(betterHotSpotChoice(none, none).chosen);
    EXPECT_EQ(betterHotSpotChoice(near, nearer).judged, 8);
    EXPECT_EQ(betterHotSpotChoice(none, reads).judged, 3);
}

/// A camera at distance 3 from the origin along @a direction, looking at the origin.
core::Camera cameraFrom(const glm::dvec3& direction)
{
    core::Camera camera;
    camera.eye = 3.0 * glm::normalize(direction);
    camera.up = std::abs(glm::normalize(direction).y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    return camera;
}

/// One hot spot on the unit sphere, its scene at volume 100 and a measure of its reveal.
struct OneHotSpotSphere {
    core::HotSpots spots;
    test::SceneFixture fixture;
    EnergyEvaluator measure;

    OneHotSpotSphere() : OneHotSpotSphere(core::makeSphere(4)) {}

private:
    explicit OneHotSpotSphere(core::SurfaceField sphere)
        : spots(core::placeHotSpots(sphere.mesh, 1)),
          fixture(withHotSpots(std::move(sphere), spots), 100),
          measure(*fixture.scene, revealOptions())
    {
    }
    static core::SurfaceField withHotSpots(core::SurfaceField sphere, const core::HotSpots& spots)
    {
        sphere.values = core::hotSpotValues(sphere.mesh, spots);
        return sphere;
    }
    static EnergyOptions revealOptions()
    {
        EnergyOptions options;
        options.reveal = true;
        options.importanceRange = {0.0f, 1.0f};
        return options;
    }
};

// One hot spot on the unit sphere, the front view alone: seen from two sides of it near the
// silhouette (more than half of it, less than 90%), no view reads, and the rule takes the judged
// view nearest to reading as its own pictures measure them, the second judged; the view from behind
// it, facing away, is not judged.
TEST(HotSpotRule, WhereNoViewReadsTheJudgedViewNearestToReadingIsTaken)
{
    const OneHotSpotSphere one;
    const glm::dvec3 toward = glm::normalize(glm::dvec3(one.spots.centres[0]));
    const glm::dvec3 side = glm::normalize(glm::cross(toward, glm::dvec3(0.3, 1.0, 0.2)));
    const glm::dvec3 otherSide = glm::cross(toward, side);
    std::vector<VisitedView> visited(3);
    const glm::dvec3 directions[3] = {glm::normalize(side + 0.5 * toward), -toward,
                                      glm::normalize(otherSide + 0.6 * toward)};
    for (int i = 0; i < 3; ++i) {
        visited[i].camera = cameraFrom(directions[i]);
        visited[i].method = render::makeMethod("front");
        visited[i].value.energy = 1.0 - 0.25 * i;
        visited[i].thetaDeg = glm::degrees(std::acos(directions[i].y));
        visited[i].phiDeg = glm::degrees(std::atan2(directions[i].x, directions[i].z));
    }
    const HotSpotChoice choice = chooseHotSpotView(visited, 0, one.measure, 8);
    EXPECT_EQ(choice.judged, 2) << "the view from behind it is not judged";
    double shortfalls[3] = {1.0, 1.0, 1.0};
    for (const int i : {0, 2}) {
        render::RenderOptions picture;
        picture.width = picture.height = kHotSpotPictureSize;
        picture.method = visited[i].method;
        const render::RenderResult result = render::renderImage(*one.fixture.scene, visited[i].camera, picture);
        shortfalls[i] = hotSpotShortfall(measurePicture(one.measure, result.layers).reveal.perRegion,
                                         hotSpotShapes(*one.measure.revealMeasure(), result.layers));
        EXPECT_GT(shortfalls[i], 0.0) << "half of it seen does not read";
        EXPECT_LT(shortfalls[i], 1.0);
    }
    ASSERT_LT(shortfalls[2], shortfalls[0]) << "the view more towards it is nearer to reading";
    const std::size_t nearest = 2;
    ASSERT_TRUE(choice.chosen);
    EXPECT_EQ(*choice.chosen, nearest);
    EXPECT_FALSE(choice.reads);
    EXPECT_EQ(choice.shortfall, shortfalls[nearest]);
    EXPECT_DOUBLE_EQ(choice.energyRatio, visited[nearest].value.energy);
    EXPECT_EQ(choice.shapes.size(), 1u);
}

// One hot spot on the unit sphere, pictured by the front view alone: seen face on it is one round
// disc, wholly seen; from the opposite side it is not seen at all.
TEST(HotSpotRule, APictureIsJudgedWhole)
{
    const OneHotSpotSphere one;
    ASSERT_EQ(one.measure.revealMeasure()->regionCount(), 1u);
    const render::MethodPtr front = render::makeMethod("front");
    const glm::dvec3 towardSpot(one.spots.centres[0]);
    EXPECT_TRUE(hotSpotsReadIn(one.measure, cameraFrom(towardSpot), front, 200));
    EXPECT_FALSE(hotSpotsReadIn(one.measure, cameraFrom(-towardSpot), front, 200));
    EXPECT_THROW(hotSpotsReadIn(EnergyEvaluator(*one.fixture.scene, EnergyOptions{}), cameraFrom(towardSpot), front, 200),
                 ValueError)
        << "no reveal measured";
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

/// The largest angle off square (degrees) over the hot spots of @a facings that face one way, seen
/// from the eye at core::kCameraDistance in the view (@a theta, @a phi).
double degreesOffSquare(const std::vector<HotSpotFacing>& facings, double theta, double phi)
{
    const glm::dvec3 eye = core::Camera::fromAngles(theta, phi).eye;
    double worst = 0.0;
    for (const HotSpotFacing& f : facings) {
        if (f.normal == glm::dvec3(0.0)) continue;
        const double sine = std::abs(glm::dot(f.normal, glm::normalize(f.centroid - eye)));
        worst = std::max(worst, glm::degrees(std::asin(sine)));
    }
    return worst;
}

// The sphere's two opposite hot spots are side-on from a band round their axis: every view offered
// lies in it, 20 degrees or more from the others, and (counted against a fine scan of the sphere of
// views) every direction of the band lies within reach of an offered view; the most side-on come
// first, and at most the number asked for.
TEST(HotSpotRule, SideOnViewsShowEveryHotSpotFromItsSide)
{
    core::SurfaceField sphere = core::makeSphere(4);
    sphere.values = core::hotSpotValues(sphere.mesh, core::placeHotSpots(sphere.mesh, 2));
    const RevealMeasure reveal(sphere, {0.0f, 1.0f});
    const std::vector<HotSpotFacing> facings = hotSpotFacings(sphere.mesh, reveal);
    ASSERT_EQ(facings.size(), 2u);
    const std::vector<std::array<double, 2>> views = sideOnViews(facings, 1000);
    ASSERT_GE(views.size(), 10u) << "a band round the sphere";
    for (std::size_t i = 0; i < views.size(); ++i) {
        EXPECT_LE(degreesOffSquare(facings, views[i][0], views[i][1]), kSideOnDeg) << i;
        if (i > 0) {
            EXPECT_GE(degreesOffSquare(facings, views[i][0], views[i][1]),
                      degreesOffSquare(facings, views[i - 1][0], views[i - 1][1]) - 1e-9)
                << "the most side-on first";
        }
        for (std::size_t j = 0; j < i; ++j) {
            const double apart = degreesBetweenViews(views[i][0], views[i][1], views[j][0], views[j][1]);
            EXPECT_GE(apart, kHotSpotViewSeparationDeg) << i << " " << j;
        }
    }
    // Every side-on direction of a finer scan lies within the separation (plus the lattice's spacing)
    // of an offered view.
    for (double theta = 0.5; theta < 180.0; theta += 2.0)
        for (double phi = 0.0; phi < 360.0; phi += 2.0) {
            if (degreesOffSquare(facings, theta, phi) > kSideOnDeg - 5.0) continue;
            double nearest = 180.0;
            for (const auto& v : views) nearest = std::min(nearest, degreesBetweenViews(theta, phi, v[0], v[1]));
            EXPECT_LT(nearest, kHotSpotViewSeparationDeg + 10.0) << theta << " " << phi;
        }
    EXPECT_EQ(sideOnViews(facings, 3).size(), 3u);
    const std::vector<std::array<double, 2>> firstThree(views.begin(), views.begin() + 3);
    EXPECT_EQ(sideOnViews(facings, 3), firstThree);
    EXPECT_TRUE(sideOnViews(facings, 0).empty());
}

// Two hot spots that face no one way (round thin parts at either end of the x axis) are side-on
// where they lie at the silhouette: seen across the x axis. One alone, or two at one place, have
// no such direction: no view is offered.
TEST(HotSpotRule, HotSpotsFacingNoOneWayAreSideOnAtTheSilhouette)
{
    HotSpotFacing left, right;
    left.centroid = glm::dvec3(-0.5, 0.0, 0.0);
    right.centroid = glm::dvec3(0.5, 0.0, 0.0);
    const std::vector<std::array<double, 2>> views = sideOnViews({left, right}, 1000);
    ASSERT_GE(views.size(), 10u) << "a band round the x axis";
    HotSpotFacing leftFacing = left, rightFacing = right;
    leftFacing.normal = glm::dvec3(-1.0, 0.0, 0.0);
    rightFacing.normal = glm::dvec3(1.0, 0.0, 0.0);
    for (const auto& view : views) EXPECT_LE(degreesOffSquare({leftFacing, rightFacing}, view[0], view[1]), kSideOnDeg);
    EXPECT_TRUE(sideOnViews({left}, 8).empty());
    EXPECT_TRUE(sideOnViews({left, left}, 8).empty());
    EXPECT_TRUE(sideOnViews({}, 8).empty());
}

/// The wrap's stable_shift of @a method.
float stableShift(const render::Method& method) { return method.values().at("stable_shift").at(0); }

// Round the view nearest to reading: first that view with the tightest rung of its readable rule,
// then its eight neighbours 4 degrees off in theta, phi or both, with its own method, kept on the
// sphere across a pole and across phi = 180; a method without the rule, or already at its
// tightest, has the neighbours only.
TEST(HotSpotRule, RoundTheNearestViewItsTighterRuleFirstThenItsNeighbours)
{
    VisitedView nearest;
    nearest.thetaDeg = 60.0;
    nearest.phiDeg = 178.0;
    nearest.method = render::makeMethod("inversevis-wrap");
    const std::vector<CandidateView> round = viewsRoundTheNearest(nearest);
    ASSERT_EQ(round.size(), 9u);
    EXPECT_EQ(round[0].thetaDeg, 60.0);
    EXPECT_EQ(round[0].phiDeg, 178.0);
    EXPECT_FLOAT_EQ(stableShift(*round[0].method), stableShift(*nearest.method) / 8.0f);
    for (std::size_t i = 1; i < round.size(); ++i) {
        EXPECT_EQ(round[i].method, nearest.method);
        EXPECT_GE(round[i].thetaDeg, 0.0);
        EXPECT_LE(round[i].thetaDeg, 180.0);
        EXPECT_LE(std::abs(round[i].phiDeg), 180.0);
        const double apart = degreesBetweenViews(nearest.thetaDeg, nearest.phiDeg, round[i].thetaDeg, round[i].phiDeg);
        EXPECT_GT(apart, 3.0) << i;
        EXPECT_LT(apart, std::sqrt(2.0) * kHotSpotNeighbourDeg) << i;
        for (std::size_t j = 1; j < i; ++j)
            EXPECT_GT(degreesBetweenViews(round[i].thetaDeg, round[i].phiDeg, round[j].thetaDeg, round[j].phiDeg), 1.0);
    }
    nearest.thetaDeg = 2.0;  // beside the pole: the neighbours beyond it lie across it
    for (const CandidateView& view : viewsRoundTheNearest(nearest)) {
        EXPECT_GE(view.thetaDeg, 0.0);
        EXPECT_LE(degreesBetweenViews(2.0, 178.0, view.thetaDeg, view.phiDeg), std::sqrt(2.0) * kHotSpotNeighbourDeg);
    }
    nearest.method = render::makeMethod("front");
    EXPECT_EQ(viewsRoundTheNearest(nearest).size(), 8u) << "no readable rule";
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    nearest.method = render::withValues(*wrap, {{"stable_shift", {wrap->info().parameter("stable_shift")->lo}}});
    EXPECT_EQ(viewsRoundTheNearest(nearest).size(), 8u) << "already at its tightest";
}

}  // namespace
}  // namespace ivis::optimize
