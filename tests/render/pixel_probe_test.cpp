// probePixel against the renderer's own layers, and facingView against the sphere's geometry and a
// point that no eye outside can see.
#include "render/scene_fixture.h"

#include <ivis/core/procedural_scenes.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/pixel_probe.h>
#include <ivis/render/renderer.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ivis::render {
namespace {

/// The angle in degrees between two directions.
double angleBetween(const glm::dvec3& a, const glm::dvec3& b)
{
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

TEST(PixelProbe, ADirectPixelShowsTheViewRaysHitAndIsSeenHeadOnFromAlongItsNormal)
{
    const RenderScene& scene = *test::sphereScene().scene;
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const PixelProbe probe = probePixel(scene, defaultMethod(), camera, 200, 200, 100.0, 100.0);
    ASSERT_EQ(probe.mapping.region, Region::Direct);
    EXPECT_NEAR(probe.mapping.point.position.z, 1.0f, 0.01f);  // the pole facing the eye
    EXPECT_GT(probe.facing.z, 0.99f);

    const std::optional<glm::dvec2> view =
        facingView(scene.bvh(), probe.mapping.point.position, probe.mapping.point.triangle, probe.facing);
    ASSERT_TRUE(view.has_value());
    const glm::dvec3 eye = core::Camera::fromAngles(view->x, view->y).eye;
    EXPECT_LT(angleBetween(eye, glm::dvec3(0.0, 0.0, 1.0)), 4.0) << view->x << " " << view->y;
    EXPECT_TRUE(seenDirectly(scene.bvh(), eye, probe.mapping.point.position, probe.mapping.point.triangle));
    // From the opposite side the sphere hides it.
    EXPECT_FALSE(seenDirectly(scene.bvh(), -eye, probe.mapping.point.position, -1));
}

TEST(PixelProbe, AnIndirectPixelShowsWhatTheRendererDrawsThereAndAViewFromBehindSeesIt)
{
    const test::SceneFixture& fixture = test::sphereScene();
    const RenderScene& scene = *fixture.scene;
    RenderOptions options;
    options.width = options.height = 160;
    options.method = makeMethod("inversevis-wrap");
    const core::Camera camera = frameView(scene, core::Camera::fromAngles(90.0, 0.0), *options.method, 1.0);
    const RenderResult picture = renderImage(scene, camera, options);
    const core::ImageLayers& layers = picture.layers;

    // Every indirect pixel of the centre row whose point lies on the far half of the sphere.
    int probed = 0;
    const int y = options.height / 2;
    for (int x = 0; x < options.width; ++x) {
        const std::size_t i = std::size_t(y) * options.width + x;
        if (layers.channel("region")[i] != 2.0f || !(layers.channel("P.Z")[i] < -0.2f)) continue;
        const PixelProbe probe = probePixel(scene, options.method, camera, options.width, options.height, x + 0.5, y + 0.5);
        ASSERT_EQ(probe.mapping.region, Region::Indirect) << x;
        const glm::vec3 drawn(layers.channel("P.X")[i], layers.channel("P.Y")[i], layers.channel("P.Z")[i]);
        EXPECT_LT(glm::length(probe.mapping.point.position - drawn), 1e-5f) << x;
        EXPECT_EQ(float(probe.mapping.point.triangle), layers.channel("triangle")[i]) << x;
        EXPECT_NEAR(probe.scalar, layers.channel("scalar")[i], 1e-6f) << x;
        // The rays arrive from outside: the side shown faces out of the sphere.
        EXPECT_GT(glm::dot(probe.facing, glm::normalize(probe.mapping.point.position)), 0.99f) << x;

        const std::optional<glm::dvec2> view =
            facingView(scene.bvh(), probe.mapping.point.position, probe.mapping.point.triangle, probe.facing);
        ASSERT_TRUE(view.has_value()) << x;
        const glm::dvec3 eye = core::Camera::fromAngles(view->x, view->y).eye;
        EXPECT_LT(angleBetween(eye, glm::dvec3(probe.mapping.point.position)), 4.0) << x;
        EXPECT_LT(glm::dot(eye, camera.eye), 0.0) << x;  // behind the picture's object
        ++probed;
    }
    EXPECT_GT(probed, 4);
}

// A curved ray's pixel tells where its ray starts and, where the method draws none, why: across a
// wrapped picture of the sphere every drawn ray starts inside its ring at the launch's speed
// 2.5 t (2 - t), a seed beyond its ring is refused as such, and a rule tighter than the rays'
// bends refuses them as unstable.
TEST(PixelProbe, ACurvedRaysPixelTellsWhereItsRayStartsAndWhyItIsNotDrawn)
{
    const RenderScene& scene = *test::sphereScene().scene;
    const int size = 160;
    // Rings 0.3 wide (0.3 radii of the unit sphere) inside the hull 0.6 wide: the seeds between lie beyond them.
    const MethodPtr method = makeMethod("inversevis-wrap", {{"ring_scale", {0.3f}}});
    core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    camera.fovYDeg = 80.0;  // beyond the hull (radius 1.6) at the picture's edge
    const float rule = method->values().at("stable_shift")[0];
    int drawn = 0, beyond = 0;
    float largestBend = 0.0f;
    std::vector<int> drawnColumns;
    for (int x = 0; x < size; ++x) {
        const PixelProbe probe = probePixel(scene, method, camera, size, size, x + 0.5, size / 2 + 0.5);
        if (probe.mapping.region == Region::Direct) {
            EXPECT_FALSE(probe.launch.has_value()) << x;
            continue;
        }
        if (!probe.launch) {
            EXPECT_EQ(probe.mapping.region, Region::Background) << x;
            continue;
        }
        const ProbedLaunch& launch = *probe.launch;
        ASSERT_TRUE(launch.ring.has_value()) << x;
        const float t = *launch.ring;
        EXPECT_GE(t, 0.0f) << x;
        EXPECT_GT(glm::length(launch.seed), 0.99f) << x << ": seeded outside the sphere";
        if (probe.mapping.region == Region::Indirect) {
            EXPECT_EQ(launch.refusal, nullptr) << x;
            EXPECT_LT(t, 1.0f) << x;
            ASSERT_TRUE(launch.speed.has_value()) << x;
            EXPECT_NEAR(*launch.speed, 2.5f * t * (2.0f - t), 1e-4f) << x;
            EXPECT_LE(launch.bend, rule) << x;
            largestBend = std::max(largestBend, launch.bend);
            drawnColumns.push_back(x);
            ++drawn;
        } else {
            ASSERT_NE(launch.refusal, nullptr) << x;
            if (std::string(launch.refusal) == "beyond its ring") {
                EXPECT_GE(t, 1.0f) << x;
                EXPECT_FALSE(launch.speed.has_value()) << x << ": refused before its launch";
                ++beyond;
            }
        }
    }
    EXPECT_GT(drawn, 8);
    EXPECT_GT(beyond, 0) << "the picture's margin lies beyond the rings";

    // Under a rule tighter than the largest bend drawn, that ray is refused as unstable.
    ASSERT_GT(largestBend, 0.0002f);
    const MethodPtr tight = makeMethod("inversevis-wrap", {{"ring_scale", {0.3f}}, {"stable_shift", {0.5f * largestBend}}});
    int unstable = 0;
    for (int x : drawnColumns) {
        const PixelProbe probe = probePixel(scene, tight, camera, size, size, x + 0.5, size / 2 + 0.5);
        if (probe.mapping.region != Region::Background) continue;
        ASSERT_TRUE(probe.launch.has_value()) << x;
        EXPECT_STREQ(probe.launch->refusal, "its landing is unstable") << x;
        EXPECT_GT(probe.launch->bend, 0.5f * largestBend) << x;
        ++unstable;
    }
    EXPECT_GT(unstable, 0);
}

TEST(FacingView, APointInsideAClosedSurfaceHasNoView)
{
    // A sphere of radius 0.5 inside the unit sphere: no eye outside sees the inner one.
    core::TriangleMesh mesh = core::makeSphere(3).mesh;
    const core::TriangleMesh inner = mesh;
    const std::uint32_t offset = std::uint32_t(mesh.positions.size());
    for (const glm::vec3& p : inner.positions) mesh.positions.push_back(0.5f * p);
    for (const auto& t : inner.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    const core::TriangleBvh bvh(mesh);

    const int innerTriangle = int(inner.triangles.size());  // the inner sphere's first triangle
    const auto& corners = mesh.triangles[std::size_t(innerTriangle)];
    const glm::vec3 point = (mesh.positions[corners[0]] + mesh.positions[corners[1]] + mesh.positions[corners[2]]) / 3.0f;
    EXPECT_FALSE(facingView(bvh, point, innerTriangle, glm::normalize(point)).has_value());

    // The outer sphere's matching point is seen from along its normal.
    const auto& outerCorners = mesh.triangles[0];
    const glm::vec3 outer =
        (mesh.positions[outerCorners[0]] + mesh.positions[outerCorners[1]] + mesh.positions[outerCorners[2]]) / 3.0f;
    const std::optional<glm::dvec2> view = facingView(bvh, outer, 0, glm::normalize(outer));
    ASSERT_TRUE(view.has_value());
    EXPECT_LT(angleBetween(core::Camera::fromAngles(view->x, view->y).eye, glm::dvec3(outer)), 4.0);
}

}  // namespace
}  // namespace ivis::render
