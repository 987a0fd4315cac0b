// inversevis-wrap against the faithful model on the measures of docs/measures.md (the unit sphere seen
// from a known view), its rings staying beside the part they surround (the vessel tree), and the
// ray it draws being exactly the one its stability rule traced, and that rule depending on the view
// ray only, not on the picture's size.
#include "render/scene_fixture.h"

#include <ivis/optimize/coherence.h>
#include <ivis/optimize/energy.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/inversevis_wrap_method.h>
#include <ivis/render/method_registry.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ivis::optimize {
namespace {

constexpr int kResolution = 1000;  // docs/measures.md measures coherence at 1000 x 1000

double surfaceVisibility(const render::RenderScene& scene, const core::Camera& camera, const render::MethodPtr& method)
{
    EnergyOptions options;
    options.resolution = kResolution;
    return EnergyEvaluator(scene, options).evaluate(camera, method).energy;
}

TEST(WrapInverseVis, ShowsMoreOfTheSphereThanTheFaithfulModelAndStaysCoherent)
{
    const auto& fixture = test::sphereScene();
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const render::MethodPtr wrap = render::makeMethod("inversevis-wrap");
    const double faithful = surfaceVisibility(*fixture.scene, camera, render::makeMethod("inversevis"));
    const double wrapped = surfaceVisibility(*fixture.scene, camera, wrap);
    // Analytic: the faithful model lands on a band (docs/method.md: about 70% with the front cap).
    EXPECT_LT(faithful, 0.75);
    EXPECT_GT(wrapped, 0.9);
    EXPECT_GE(measureCoherence(*fixture.scene, camera, wrap, kResolution).value(), 0.99);
}

/// Share of the landed rays of @a name on the vessel tree that land within the height of their
/// seed plus @a radii local radii of the surface point closest to the seed.
double landingBesideSeed(const std::string& name, float radii)
{
    const auto& fixture = test::vesselScene();
    const render::RenderScene& scene = *fixture.scene;
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const core::CameraFrame frame(camera, 200, 200);
    const render::MethodPtr method = render::makeMethod(name);
    const render::CurvedRayMap rays(scene, frame, *method->curved());
    auto sampler = scene.distance().sampler();
    std::size_t landed = 0, beside = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) {
            render::CurvedRayStart start;
            if (!rays.start(x + 0.5, y + 0.5, sampler, start)) continue;
            const render::PixelMapping landing = rays.landing(start, sampler);
            if (landing.region != render::Region::Indirect) continue;
            int triangle = -1;
            const core::TrianglePoint closest = scene.bvh().closestPoint(glm::dvec3(start.seed), 10.0, triangle);
            if (triangle < 0) return 0.0;
            const auto& corners = scene.mesh().triangles[std::size_t(triangle)];
            float radius = 0.0f;
            for (int k = 0; k < 3; ++k) radius += float(closest.barycentric[k]) * render::wrapLocalRadii(scene)[corners[k]];
            const float height = glm::length(start.seed - glm::vec3(closest.point));
            ++landed;
            if (glm::length(landing.point.position - glm::vec3(closest.point)) <= height + radii * radius) ++beside;
        }
    EXPECT_GT(landed, 2000u) << name;
    return double(beside) / double(landed);
}

TEST(WrapInverseVis, EachRingLandsOnThePartItSurrounds)
{
    // The back side of each branch appears beside it: a ray lands within the height of its seed
    // plus a few local radii (half the part's circumference is pi radii) of where its view ray
    // passed closest. Measured with rings of 12 radii and the default rule 0.1: 85.5% within pi
    // radii, 96.0% within 6, 98.4% within 8, 99.6% within 10, 99.97% within 12 (with the rule's
    // speed probes at 0.04: 84.7, 95.7, 98.3, 99.6, 99.97%; at 0.005: 99.4% within 8; with rings
    // of 4: 96.6% within pi, 99.7% within 6).
    EXPECT_GE(landingBesideSeed("inversevis-wrap", 10.0f), 0.99);
}

TEST(WrapInverseVis, DrawsTheRayItsStabilityRuleTraced)
{
    // The rule traces the ray it draws; traceMany takes that end instead of tracing it again, and
    // must give exactly what tracing it again gives.
    const auto& fixture = test::vesselScene();
    const render::RenderScene& scene = *fixture.scene;
    const core::CameraFrame frame(core::Camera::fromAngles(70.0, 30.0), 120, 120);
    const render::MethodPtr method = render::makeMethod("inversevis-wrap");
    const render::CurvedRayMap rays(scene, frame, *method->curved());
    auto sampler = scene.distance().sampler();
    std::vector<render::CurvedRayStart> starts;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            render::CurvedRayStart start;
            if (rays.start(x + 0.5, y + 0.5, sampler, start)) starts.push_back(start);
        }
    ASSERT_GT(starts.size(), 1000u);
    std::vector<render::CurvedRayStart> untraced = starts;
    for (render::CurvedRayStart& start : untraced) {
        ASSERT_TRUE(start.traced.has_value());
        start.traced.reset();
    }
    std::vector<render::CurvedRayTrace> kept(starts.size()), again(starts.size());
    rays.traceMany(starts.data(), starts.size(), sampler, kept.data());
    rays.traceMany(untraced.data(), untraced.size(), sampler, again.data());
    for (std::size_t i = 0; i < starts.size(); ++i) {
        EXPECT_EQ(kept[i].end.position, again[i].end.position) << i;
        EXPECT_EQ(kept[i].end.velocity, again[i].end.velocity) << i;
        EXPECT_EQ(kept[i].end.steps, again[i].end.steps) << i;
        EXPECT_TRUE(kept[i].end.landed && again[i].end.landed) << "only stable landings are drawn";
    }
}

/// Exact distances to the mesh of the ends of the rays @a method draws on the unit sphere, in fine voxels.
std::vector<double> landingHeights(const render::MethodPtr& method)
{
    const auto& fixture = test::sphereScene();
    const render::RenderScene& scene = *fixture.scene;
    const core::CameraFrame frame(core::Camera::fromAngles(70.0, 30.0), 160, 160);
    const render::CurvedRayMap rays(scene, frame, *method->curved());
    auto sampler = scene.distance().sampler();
    std::vector<double> heights;
    for (int y = 0; y < 160; ++y)
        for (int x = 0; x < 160; ++x) {
            render::CurvedRayStart start;
            if (!rays.start(x + 0.5, y + 0.5, sampler, start)) continue;
            int triangle = -1;
            const glm::dvec3 end(start.traced->position);
            const core::TrianglePoint closest = scene.bvh().closestPoint(end, 1.0, triangle);
            heights.push_back(glm::length(end - closest.point) / scene.distance().voxelSize());
        }
    std::sort(heights.begin(), heights.end());
    return heights;
}

TEST(WrapInverseVis, LandsItsRaysCloserToTheSurfaceThanHalfAVoxel)
{
    // A ray lands where the sampled phi falls below `landing` fine voxels (0.1; the paper's model:
    // 0.5): the exact distance of its end to the mesh is that, within the field's interpolation.
    // Measured on 12,013 rays: median 0.099, 99th percentile 0.111, largest 0.118 voxel; with
    // landing 0.5: 0.482, 0.507, 0.515.
    const std::vector<double> heights = landingHeights(render::makeMethod("inversevis-wrap"));
    ASSERT_GT(heights.size(), 2000u);
    EXPECT_LT(heights[heights.size() * 99 / 100], 0.15);
    EXPECT_LT(heights.back(), 0.2);
    const std::vector<double> paper = landingHeights(render::makeMethod("inversevis-wrap", {{"landing", {0.5f}}}));
    ASSERT_GT(paper.size(), 2000u);
    EXPECT_GT(paper[paper.size() / 2], 0.4) << "the threshold reaches the rays";
}

TEST(WrapInverseVis, ItsStabilityRuleDependsOnTheViewRayNotOnThePicturesSize)
{
    // The rule probes the rays of the neighbouring pixels a fixed step (about a pixel of a
    // 1000-pixel picture) further in and out, whatever the picture's size: the annealing's small
    // pictures then draw the rays the 1000 x 1000 picture draws. Pixel (x, y) of a 40 x 40 picture
    // and pixel (3x + 1, 3y + 1) of a 120 x 120 one share their centre's view ray.
    const auto& fixture = test::vesselScene();
    const render::RenderScene& scene = *fixture.scene;
    const core::Camera camera = core::Camera::fromAngles(70.0, 30.0);
    const core::CameraFrame coarse(camera, 40, 40), fine(camera, 120, 120);
    const render::MethodPtr method = render::makeMethod("inversevis-wrap");
    const render::CurvedRayMap coarseRays(scene, coarse, *method->curved()), fineRays(scene, fine, *method->curved());
    auto sampler = scene.distance().sampler();
    int seeded = 0, drawn = 0, agree = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            render::CurvedRayStart a, b;
            const bool drawnA = coarseRays.start(x + 0.5, y + 0.5, sampler, a);
            const bool drawnB = fineRays.start(3 * x + 1.5, 3 * y + 1.5, sampler, b);
            if (!a.ring && !b.ring) continue;  // a direct hit, no seed or no surface near it in both
            ++seeded;
            drawn += drawnA;
            agree += drawnA == drawnB;
            if (drawnA && drawnB) {
                EXPECT_NEAR(a.bend, b.bend, 1e-3f) << x << " " << y;
            }
        }
    ASSERT_GT(drawn, 100);
    EXPECT_GE(agree, seeded - seeded / 100) << "of " << seeded << " seeded pixels";
}

}  // namespace
}  // namespace ivis::optimize
