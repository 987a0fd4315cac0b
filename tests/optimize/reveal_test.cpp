// Hot-spot reveal on the sphere's two opposite hot spots: the one in view is fully revealed, the
// one behind it not at all by the direct picture.
#include "render/scene_fixture.h"

#include <ivis/core/hot_spots.h>
#include <ivis/optimize/energy.h>
#include <ivis/render/method_registry.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace ivis::optimize {
namespace {

TEST(Reveal, AHotSpotInViewIsFullyRevealedAndItsOppositeIsNot)
{
    static const test::SceneFixture fixture = [] {
        core::SurfaceField sphere = core::makeSphere(4);
        sphere.values = core::hotSpotValues(sphere.mesh, core::placeHotSpots(sphere.mesh, 2));
        sphere.name = "hotspots";
        return test::SceneFixture(std::move(sphere), 200);
    }();
    const core::HotSpots spots = core::placeHotSpots(fixture.field.mesh, 2);
    EnergyOptions options;
    options.resolution = 600;
    options.reveal = true;
    const EnergyEvaluator evaluator(*fixture.scene, options);
    ASSERT_EQ(evaluator.revealMeasure()->regionCount(), 2u);
    // Look at the first spot from outside along its own direction.
    const glm::dvec3 eye = 2.5 * glm::normalize(glm::dvec3(spots.centres[0]));
    core::Camera camera;
    camera.eye = eye;
    camera.up = std::abs(eye.y) < 2.0 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    camera.fovYDeg = 25.0;  // rays close enough to land in the slivers of voxels the spot's rim cuts
    const EnergyValue front = evaluator.evaluate(camera, render::makeMethod("front"));
    EXPECT_DOUBLE_EQ(front.reveal.direct, front.reveal.total);
    ASSERT_EQ(front.reveal.perRegion.size(), 2u);
    const double seen = std::max(front.reveal.perRegion[0], front.reveal.perRegion[1]);
    const double hidden = std::min(front.reveal.perRegion[0], front.reveal.perRegion[1]);
    EXPECT_NEAR(seen, 1.0, 1e-5) << "the spot in view (the rays miss a few corner slivers, of almost no area)";
    EXPECT_DOUBLE_EQ(hidden, 0.0) << "the spot behind";
    EXPECT_NEAR(front.reveal.total, 0.5, 0.05);
}

}  // namespace
}  // namespace ivis::optimize
