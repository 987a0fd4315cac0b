// The unseen map against the measure it draws: a sphere seen from the front shows its front grey
// and its back red; every surface voxel seen leaves no red, none seen leaves (almost) no grey.
#include "render/scene_fixture.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/unseen_map.h>
#include <ivis/render/method_registry.h>

#include <gtest/gtest.h>

namespace ivis::optimize {
namespace {

/// Red, grey and white pixels of one panel of an unseen map.
struct PanelCounts {
    int red = 0, grey = 0, white = 0;
};

PanelCounts countPanel(const core::Image& map, int panel)
{
    PanelCounts counts;
    const int size = map.height();
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::vec4& c = map.at(panel * size + x, y);
            if (c == glm::vec4(1.0f))
                ++counts.white;
            else if (c.r > 0.25f && c.g < 0.05f && c.b < 0.05f)
                ++counts.red;
            else if (c.r == c.g && c.g == c.b)
                ++counts.grey;
        }
    return counts;
}

TEST(UnseenMap, ShowsTheFrontOfASphereSeenAndItsBackUnseen)
{
    const auto& fixture = test::sphereScene();
    EnergyOptions options;
    options.resolution = 300;
    const EnergyEvaluator evaluator(*fixture.scene, options);
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const EnergyValue value = evaluator.evaluate(camera, render::makeMethod("front"));
    const int size = 160;
    const core::Image map = unseenMap(*fixture.scene, camera, *evaluator.surfaceVoxels(), value.seenVoxels, size);
    ASSERT_EQ(map.width(), 2 * size);
    ASSERT_EQ(map.height(), size);
    const PanelCounts along = countPanel(map, 0), opposite = countPanel(map, 1);
    // Each panel shows the sphere framed (a disc of about half the panel) and nothing else.
    for (const PanelCounts& panel : {along, opposite}) {
        EXPECT_EQ(panel.red + panel.grey + panel.white, size * size);
        EXPECT_GT(panel.red + panel.grey, size * size / 3);
    }
    // The front shows its own surface (but for voxels the grazing rim's pixels miss); from behind
    // only a thin rim of it is in sight.
    EXPECT_LT(along.red, (along.red + along.grey) / 10);
    EXPECT_GT(opposite.red, 9 * (opposite.red + opposite.grey) / 10);
}

TEST(UnseenMap, IsAllGreyWhenEverySurfaceVoxelIsSeenAndAllRedWhenNone)
{
    const auto& fixture = test::sphereScene();
    const SurfaceVoxels voxels(fixture.scene->mesh());
    const core::Camera camera = core::Camera::fromAngles(40.0, 70.0);
    const int size = 96;
    const core::Image all = unseenMap(*fixture.scene, camera, voxels, voxels.keys(), size);
    const core::Image none = unseenMap(*fixture.scene, camera, voxels, {}, size);
    for (int panel : {0, 1}) {
        const PanelCounts seen = countPanel(all, panel), unseen = countPanel(none, panel);
        EXPECT_EQ(seen.red, 0);
        EXPECT_GT(seen.grey, size * size / 3);
        // A hit point lies in a surface voxel (the surface is sampled finely), but for one rounded
        // across a voxel face now and then: almost no grey is left.
        EXPECT_LE(unseen.grey, seen.grey / 1000);
        EXPECT_EQ(unseen.red + unseen.grey, seen.grey);
    }
    EXPECT_THROW(unseenMap(*fixture.scene, camera, voxels, {}, 4), ValueError);
}

}  // namespace
}  // namespace ivis::optimize
