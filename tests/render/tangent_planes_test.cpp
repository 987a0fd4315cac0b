// Curved rays on checked tangent planes (render/tangent_planes.h) against the same rays with every
// step sampled: exact where the field is a plane, stepped again where a plane fails its check, and
// within a tenth of a voxel on real volumes (docs/rendering.md, "Tangent planes near the landing").
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/core/procedural_scenes.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/framing.h>
#include <ivis/render/tangent_planes.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ivis::render {
namespace {

constexpr float kVoxel = 0.01f;  ///< the fine voxel of the analytic fields

/// phi = z, bent by @a kink * (x - kinkAt) beyond x = kinkAt; counts its samples.
struct AnalyticField {
    float kink = 0.0f;
    float kinkAt = 0.0f;
    int samples = 0;

    float phiAndGradient(const glm::vec3& p, glm::vec3& gradient)
    {
        ++samples;
        const bool bent = kink != 0.0f && p.x > kinkAt;
        gradient = glm::vec3(bent ? kink : 0.0f, 0.0f, 1.0f);
        return p.z + (bent ? kink * (p.x - kinkAt) : 0.0f);
    }
};

/// The flight of one ray on tangent planes to its end.
CurvedRayEnd flyOnPlanes(AnalyticField& field, const glm::vec3& seed, const glm::vec3& velocity,
                         const CurvedRayParams& params, float epsilon)
{
    CurvedRayFlight flight(seed, velocity);
    const TangentPlaneRule rule = tangentPlaneRule(kVoxel);
    while (flight.end().steps < params.maxSteps && flight.advance<true>(field, rule, params.stepSize, epsilon, 10.0f)) {
    }
    return flight.end();
}

TEST(TangentPlanes, OnAPlaneFieldTheyStepAsEverySampleDoesWithFewerSamples)
{
    CurvedRayParams params;
    const float epsilon = 0.01f * kVoxel;
    for (const float speed : {0.0f, 0.05f, 0.3f}) {
        const glm::vec3 seed(0.0f, 0.0f, 0.05f), velocity(speed, 0.0f, -0.01f);
        AnalyticField planes, everyStep;
        const CurvedRayEnd onPlanes = flyOnPlanes(planes, seed, velocity, params, epsilon);
        const CurvedRayEnd sampled = integrateCurvedRay(everyStep, seed, velocity, params, epsilon, 10.0f);
        ASSERT_TRUE(sampled.landed) << speed;
        EXPECT_TRUE(onPlanes.landed) << speed;
        EXPECT_EQ(onPlanes.steps, sampled.steps) << speed;
        EXPECT_LT(glm::length(onPlanes.position - sampled.position), 1e-3f * kVoxel) << speed;
        // Below a voxel (most of the steps from 5 voxels up to a hundredth) a sample serves 17 steps.
        EXPECT_LT(planes.samples, everyStep.samples / 2) << speed;
    }
}

TEST(TangentPlanes, APlaneThatFailsItsCheckIsSteppedAgainSampleBySample)
{
    // A ray creeping along +x below a voxel crosses a kink where the gradient turns by 0.5: the
    // plane from before the kink would carry the flat field past it; its check at the segment's
    // end fails, and the ray steps from the plane's sample again as every-step sampling does.
    CurvedRayParams params;
    const float epsilon = 0.001f * kVoxel;
    const glm::vec3 seed(0.0f, 0.0f, 0.5f * kVoxel), velocity(1.0f, 0.0f, 0.0f);
    for (const float kinkAt : {0.0005f, 0.001f, 0.002f}) {
        AnalyticField planes{0.5f, kinkAt}, everyStep{0.5f, kinkAt}, flat;
        const CurvedRayEnd onPlanes = flyOnPlanes(planes, seed, velocity, params, epsilon);
        const CurvedRayEnd sampled = integrateCurvedRay(everyStep, seed, velocity, params, epsilon, 10.0f);
        const CurvedRayEnd flatEnd = integrateCurvedRay(flat, seed, velocity, params, epsilon, 10.0f);
        ASSERT_TRUE(sampled.landed) << kinkAt;
        ASSERT_GT(glm::length(flatEnd.position - sampled.position), 0.1f * kVoxel) << "the kink must matter";
        EXPECT_TRUE(onPlanes.landed) << kinkAt;
        EXPECT_LT(glm::length(onPlanes.position - sampled.position), 1e-3f * kVoxel) << kinkAt;
    }
}

/// Each drawn ray of a 200 x 200 picture of @a scene traced by CurvedRayMap (on tangent planes
/// where the volume has a fine band) and again with every step sampled: at least 99% land within
/// a tenth of a fine voxel. Returns the share of the rays whose landings differ at all (where
/// planes served).
double expectEveryStepsLandings(const RenderScene& scene, const core::Camera& view)
{
    const MethodPtr method = makeMethod("inversevis-wrap");
    const int size = 200;
    const core::CameraFrame frame(frameView(scene, view, *method, 1.0), size, size);
    const CurvedRayMap rays(scene, frame, *method->curved());
    auto sampler = scene.distance().sampler();
    const CurvedRayParams& params = method->curved()->rayParams();
    const float epsilon = landingEpsilon(params, scene.distance()), escape = escapeDistance(scene.distance());
    const float voxel = scene.distance().voxelSize();
    std::size_t drawn = 0, off = 0, differ = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            CurvedRayStart start;
            if (!rays.start(x + 0.5, y + 0.5, sampler, start)) continue;
            const CurvedRayEnd planes = rays.trace(start, sampler).end;
            const glm::vec3 velocity = method->curved()->launchVelocity(start, 0);
            const CurvedRayEnd sampled = integrateCurvedRay(sampler, start.seed, velocity, params, epsilon, escape);
            ++drawn;
            const float apart = planes.landed == sampled.landed ? glm::length(planes.position - sampled.position)
                                                                : std::numeric_limits<float>::infinity();
            if (apart > 0.1f * voxel) ++off;
            if (apart > 0.0f) ++differ;
        }
    EXPECT_GT(drawn, 2000u);
    EXPECT_LE(off, drawn / 100);
    return double(differ) / double(std::max<std::size_t>(drawn, 1));
}

TEST(TangentPlanes, OnTheVolumeTheyLandWithinATenthOfAVoxelOfEverySample)
{
    // Where the surface is smooth on the scale of the voxels, planes serve nearly every ray.
    ASSERT_TRUE(test::sphereWithFarField().scene->distance().hasFineBand());
    EXPECT_GT(expectEveryStepsLandings(*test::sphereWithFarField().scene, core::Camera::fromAngles(90.0, 0.0)), 0.5);
    const test::SceneFixture armadillo(core::loadSurface(test::sharedMesh("armadillo_50k.ply")), 300, 100);
    EXPECT_GT(expectEveryStepsLandings(*armadillo.scene, core::Camera::fromAngles(90.0, 0.0)), 0.5);
    // A thin vessel curves within a few voxels: there the rule declines most planes, and those it
    // starts must still hold.
    const test::SceneFixture tree(core::makeVesselTree(), 160, 40);
    expectEveryStepsLandings(*tree.scene, core::Camera::fromAngles(70.0, 30.0));
}

}  // namespace
}  // namespace ivis::render
