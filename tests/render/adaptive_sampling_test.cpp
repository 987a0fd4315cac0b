// Adaptive image sampling against the full trace: the same regions and the same landings (the
// criteria of docs/rendering.md, "Adaptive image sampling"), on the generated vessel tree (its far
// field the fine grid, and one four times coarser) and a real artery, and the bracketed valley
// search against the whole-ray one.
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/core/procedural_scenes.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ivis::render {
namespace {

/// How the adaptive picture of one view differs from the full trace's.
struct PictureDifference {
    std::size_t pixels = 0;
    std::size_t regionDiffers = 0;     ///< pixels whose region differs
    std::size_t indirectInBoth = 0;
    std::size_t landingsOff = 0;       ///< of those, landings more than a tenth of a voxel apart
    RenderStats adaptive;
};

PictureDifference compareWithFullTrace(const RenderScene& scene, const core::Camera& camera, const std::string& method,
                                       int size, const ParameterValues& values = {})
{
    RenderOptions options;
    options.width = options.height = size;
    options.method = makeMethod(method, values);
    options.legend = false;
    RenderOptions full = options;
    full.adaptive.enabled = false;
    const RenderResult a = renderImage(scene, camera, options), f = renderImage(scene, camera, full);
    const float tenth = 0.1f * scene.distance().voxelSize();
    PictureDifference d;
    d.adaptive = a.stats;
    const core::Channel &ra = a.layers.channel("region"), &rf = f.layers.channel("region");
    d.pixels = ra.size();
    for (std::size_t i = 0; i < ra.size(); ++i) {
        if (ra[i] != rf[i]) ++d.regionDiffers;
        if (ra[i] != float(Region::Indirect) || rf[i] != float(Region::Indirect)) continue;
        ++d.indirectInBoth;
        glm::vec3 pa, pf;
        for (int c = 0; c < 3; ++c) {
            const std::string layer = std::string("P.") + "XYZ"[c];
            pa[c] = a.layers.channel(layer)[i];
            pf[c] = f.layers.channel(layer)[i];
        }
        if (glm::length(pa - pf) > tenth) ++d.landingsOff;
    }
    return d;
}

/// The criteria: regions differ on at most 0.1% of the pixels, landings lie within a tenth of a
/// voxel on at least 99% of the indirect pixels.
void expectSamePicture(const PictureDifference& d, const std::string& name)
{
    ASSERT_GT(d.indirectInBoth, d.pixels / 10) << name << ": too few indirect pixels to compare";
    EXPECT_LE(d.regionDiffers, d.pixels / 1000) << name;
    EXPECT_LE(d.landingsOff, d.indirectInBoth / 100) << name;
}

TEST(AdaptiveSampling, TheWrapsPictureIsTheFullTracesOnTheVesselTree)
{
    const auto& fixture = test::vesselScene();
    for (const core::Camera& camera : {core::Camera::fromAngles(70.0, 30.0), core::Camera::fromAngles(120.0, 200.0)}) {
        const PictureDifference d = compareWithFullTrace(*fixture.scene, camera, "inversevis-wrap", 400);
        expectSamePicture(d, "vessel tree");
        // It did sample adaptively: seeds from the lattice, background skipped.
        EXPECT_GT(d.adaptive.seedsInterpolated, d.indirectInBoth / 10);
        EXPECT_GT(d.adaptive.pixelsSkipped, d.pixels / 10);
    }
}

TEST(AdaptiveSampling, TheWrapsPictureIsTheFullTracesWhereTheFarFieldIsCoarser)
{
    // A far field four times coarser than the band, as at volume 800 (200): the lattice's seeds
    // start from their block's corners' bottoms and the view rays' samples come from far cells'
    // quartics (docs/rendering.md, "Adaptive image sampling" and "phi along a view ray").
    const test::SceneFixture fixture(core::makeVesselTree(), 160, 40);
    ASSERT_TRUE(fixture.scene->distance().hasFineBand());
    const PictureDifference d =
        compareWithFullTrace(*fixture.scene, core::Camera::fromAngles(70.0, 30.0), "inversevis-wrap", 400);
    expectSamePicture(d, "vessel tree, far field 40");
    EXPECT_GT(d.adaptive.seedsInterpolated, d.indirectInBoth / 10);
}

TEST(AdaptiveSampling, TheWrapsPictureIsTheFullTracesOnARealArtery)
{
    const core::SurfaceField artery = core::loadSurface(test::sharedMesh("vampy_artery_cfd_pressure.ply"));
    const test::SceneFixture fixture(artery, 200);
    const core::Camera camera = core::Camera::fromAngles(54.7356, 135.0, core::kCameraDistance, 60.0);
    expectSamePicture(compareWithFullTrace(*fixture.scene, camera, "inversevis-wrap", 400), "artery");
    // A rule so tight that it refuses most rays: only the rays it draws are drawn.
    expectSamePicture(compareWithFullTrace(*fixture.scene, camera, "inversevis-wrap", 400, {{"stable_shift", {0.01f}}}),
                      "artery, stable_shift 0.01");
}

TEST(AdaptiveSampling, ABracketedValleySearchFindsTheWholeRaysSeed)
{
    // Seeking the bottom only near a guess within the reach finds the seed the search along the
    // whole ray finds; a guess beyond the reach does not.
    const auto& fixture = test::vesselScene();
    const RenderScene& scene = *fixture.scene;
    auto sampler = scene.distance().sampler();
    const float voxel = scene.distance().voxelSize(), hull = 0.6f;
    const core::Bounds3 box = hullBounds(scene.bounds(), hull, voxel);
    const core::CameraFrame frame(core::Camera::fromAngles(70.0, 30.0), 200, 200);
    int compared = 0, exact = 0, far = 0;
    for (int y = 0; y < 200; y += 7)
        for (int x = 0; x < 200; x += 7) {
            const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
            const glm::vec3 origin(ray.origin), direction(ray.direction);
            glm::vec3 seed, near;
            float distance, nearDistance, bottom;
            if (!findClosestApproach(sampler, origin, direction, hull, box, seed, distance, &bottom)) continue;
            for (const float off : {-0.7f, 0.0f, 0.7f}) {
                ASSERT_TRUE(findClosestApproachNear(sampler, origin, direction, hull, box, bottom + off * voxel, voxel,
                                                    near, nearDistance));
                // The same bottom, or a neighbouring bump of the field in the same flat valley.
                EXPECT_LT(glm::length(near - seed), 0.05f * voxel) << x << " " << y << " off " << off;
                exact += glm::length(near - seed) < 0.001f * voxel;
            }
            ++compared;
            // Twenty voxels off, with a reach of one: the bottom found is often not the ray's.
            if (findClosestApproachNear(sampler, origin, direction, hull, box, bottom + 20.0f * voxel, voxel, near,
                                        nearDistance) &&
                glm::length(near - seed) > voxel)
                ++far;
        }
    ASSERT_GT(compared, 100);
    EXPECT_GT(exact, 3 * compared * 95 / 100);
    EXPECT_GT(far, compared / 4);
}

}  // namespace
}  // namespace ivis::render
