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
