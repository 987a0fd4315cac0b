// Curved rays on the unit sphere against the analytic picture of docs/method.md, one integrator step
// against the formula, and the view ray's closest approach against the sphere and brute force.
#include "render/scene_fixture.h"

#include <ivis/core/camera.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/ray_box.h>
#include <ivis/render/curved_ray.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace ivis::render {
namespace {

/// The box around the unit sphere's hull.
core::Bounds3 hullBox()
{
    const auto& fixture = test::sphereScene();
    return hullBounds(fixture.scene->bounds(), 0.4f, fixture.scene->distance().voxelSize());
}

/// Landing points of the curved rays of a column of pixels sweeping from the sphere's silhouette to
/// past the hull's, camera at (0, 0, 2.5) looking down -z.
std::vector<CurvedRayEnd> sweep(float alpha, std::vector<glm::vec3>* seeds = nullptr)
{
    const auto& fixture = test::sphereScene();
    auto sampler = fixture.scene->distance().sampler();
    CurvedRayParams params;
    const float eps = landingEpsilon(params, fixture.scene->distance());
    std::vector<CurvedRayEnd> ends;
    const glm::vec3 eye(0.0f, 0.0f, 2.5f);
    for (int i = 0; i <= 200; ++i) {
        const float angle = glm::radians(20.0f + 15.0f * float(i) / 200.0f);  // sphere edge 23.6, hull 34 deg
        const glm::vec3 direction(std::sin(angle) * 0.6f, std::sin(angle) * 0.8f, -std::cos(angle));
        glm::vec3 seed;
        if (glm::length(glm::cross(direction, eye)) < 1.01f) continue;  // the view ray hits the sphere
        if (!findHullExit(sampler, eye, direction, params.hullOffset, hullBox(), seed)) continue;
        glm::vec3 gradient;
        sampler.phiAndGradient(seed, gradient);
        ends.push_back(traceCurvedRay(sampler, seed, initialVelocity(gradient, direction, alpha), params, eps));
        if (seeds) seeds->push_back(seed);
    }
    return ends;
}

TEST(CurvedRay, HullExitIsFarthestCrossingOfAnalyticHull)
{
    const auto& fixture = test::sphereScene();
    auto sampler = fixture.scene->distance().sampler();
    const glm::vec3 eye(0.0f, 0.0f, 2.5f);
    const glm::vec3 direction = glm::normalize(glm::vec3(0.5f, 0.0f, -1.0f));
    glm::vec3 seed;
    ASSERT_TRUE(findHullExit(sampler, eye, direction, 0.4f, hullBox(), seed));
    // Far root of |eye + t d| = 1.4.
    const float b = glm::dot(eye, direction), c = glm::dot(eye, eye) - 1.4f * 1.4f;
    const float tFar = -b + std::sqrt(b * b - c);
    EXPECT_LT(glm::length(seed - (eye + tFar * direction)), 0.01f);
    EXPECT_FALSE(findHullExit(sampler, eye, glm::normalize(glm::vec3(1.0f, 0.0f, -0.5f)), 0.4f, hullBox(), seed));
}

// findHullExits clears groups of neighbouring rays with one cone: each ray must still get its own
// farthest crossing (findHullExit's), for a perspective fan (one origin), parallel rays (an orthographic camera)
// and groups whose rays point far apart.
TEST(CurvedRay, HullExitsOfManyRaysAreEachRaysOwn)
{
    const auto& fixture = test::sphereScene();
    auto sampler = fixture.scene->distance().sampler();
    const glm::vec3 eye(0.0f, 0.0f, 2.5f);
    std::vector<glm::vec3> origins, directions;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            const float u = -1.0f + 2.0f * (x + 0.5f) / 120.0f, v = -1.0f + 2.0f * (y + 0.5f) / 120.0f;
            origins.push_back(eye);  // perspective
            directions.push_back(glm::normalize(glm::vec3(u, v, -1.0f)));
            origins.push_back(glm::vec3(2.0f * u, 2.0f * v, 2.5f));  // orthographic
            directions.push_back(glm::vec3(0.0f, 0.0f, -1.0f));
        }
    const std::size_t rows = origins.size();
    for (std::size_t i = 0; i < rows; i += 7) {  // scattered rays, grouped together
        origins.push_back(origins[(i * 7919) % rows]);
        directions.push_back(directions[(i * 7919) % rows]);
    }
    std::vector<glm::vec3> seeds(origins.size());
    std::unique_ptr<bool[]> found(new bool[origins.size()]);
    findHullExits(sampler, origins.data(), directions.data(), origins.size(), 0.4f, hullBox(), seeds.data(),
                  found.get());
    int hits = 0;
    for (std::size_t i = 0; i < origins.size(); ++i) {
        glm::vec3 seed;
        const bool one = findHullExit(sampler, origins[i], directions[i], 0.4f, hullBox(), seed);
        ASSERT_EQ(found[i], one) << i;
        if (!one) continue;
        ++hits;
        EXPECT_LT(glm::length(seeds[i] - seed), 1e-4f) << i;
    }
    EXPECT_GT(hits, 5000);
    EXPECT_LT(hits, int(origins.size()) - 5000);
}

/// The least phi along origin + t direction over the hull box, sampled every 0.0005 (brute force).
float bruteClosestApproach(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                           const core::Bounds3& box)
{
    float tEnter, tExit, least = 1e9f;
    if (!core::rayBoxInterval(origin, direction, box, tEnter, tExit)) return least;
    for (float t = tEnter; t <= tExit; t += 0.0005f) least = std::min(least, sampler.phi(origin + t * direction));
    return least;
}

TEST(CurvedRay, ClosestApproachIsTheLeastDistanceAlongTheRay)
{
    // On the sphere the view ray at angle a from the axis passes the centre at 2.5 sin a: its least
    // distance is 2.5 sin a - 1. On the vessel tree rays pass several branches (several local
    // minima): the search must find the least of them, as brute force does, within a quarter voxel.
    const glm::vec3 eye(0.0f, 0.0f, 2.5f);
    {
        const auto& fixture = test::sphereScene();
        auto sampler = fixture.scene->distance().sampler();
        for (float degrees = 24.0f; degrees < 33.0f; degrees += 0.5f) {
            const float angle = glm::radians(degrees);
            const glm::vec3 direction(std::sin(angle) * 0.6f, std::sin(angle) * 0.8f, -std::cos(angle));
            glm::vec3 seed;
            float distance;
            ASSERT_TRUE(findClosestApproach(sampler, eye, direction, 0.4f, hullBox(), seed, distance)) << degrees;
            EXPECT_NEAR(distance, 2.5f * std::sin(angle) - 1.0f, 0.002f) << degrees;
            // Where the radius meets the ray at a right angle, within what the field decides: along
            // the ray phi stays within 1e-3 of its least for about +-0.05.
            EXPECT_NEAR(glm::dot(seed - eye, direction), glm::dot(-eye, direction), 0.06f) << degrees;
        }
    }
    const auto& fixture = test::vesselScene();
    auto sampler = fixture.scene->distance().sampler();
    const float quarterVoxel = 0.25f * fixture.scene->distance().voxelSize();
    const core::Bounds3 box = hullBounds(fixture.scene->bounds(), 0.4f, fixture.scene->distance().voxelSize());
    const core::CameraFrame frame(core::Camera::fromAngles(90.0, 0.0), 60, 60);
    int found = 0;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 60; ++x) {
            const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
            const glm::vec3 origin(ray.origin), direction(ray.direction);
            if (fixture.scene->bvh().intersect(origin, direction).hit()) continue;
            const float least = bruteClosestApproach(sampler, origin, direction, box);
            glm::vec3 seed;
            float distance;
            const bool approached = findClosestApproach(sampler, origin, direction, 0.4f, box, seed, distance);
            // The seed is the centre of the valley round the least, where phi stays within
            // kClosestApproachValley voxels of it (and an eighth of a voxel more between samples).
            const float valley = (kClosestApproachValley + 0.125f) * 4.0f * quarterVoxel;
            if (least < 0.4f - valley) {
                ASSERT_TRUE(approached) << x << ", " << y;
                ++found;
                EXPECT_GE(distance, least - quarterVoxel) << x << ", " << y;
                EXPECT_LE(distance, least + valley) << x << ", " << y;
            } else if (least > 0.4f) {
                EXPECT_FALSE(approached) << x << ", " << y;
            }
        }
    EXPECT_GT(found, 600);
}

// A view ray that skims a flat face at a constant height meets no single closest point: phi is the
// same all along the face. The seed is the face's middle for every such ray, so that neighbouring
// pixels' seeds stay together (the lowest sample alone fell anywhere along the face).
TEST(CurvedRay, HintedClosestApproachFindsTheRaysLowestValleyFromAnyHint)
{
    // On the vessel tree a view ray passes several branches: a hint at its own bottom, a few voxels
    // off it, or at the middle of its interval (often another branch's valley) must lead to the
    // valley findClosestApproach finds, its seed within a hundredth of a voxel. (Its bottom may be
    // another of a flat valley's voxel-sized bumps, the valley's centre not.)
    const auto& fixture = test::vesselScene();
    auto sampler = fixture.scene->distance().sampler();
    const float voxel = fixture.scene->distance().voxelSize();
    const core::Bounds3 box = hullBounds(fixture.scene->bounds(), 0.4f, voxel);
    const core::CameraFrame frame(core::Camera::fromAngles(60.0, 30.0), 50, 50);
    int approached = 0, hintedElsewhere = 0;
    for (int y = 0; y < 50; ++y)
        for (int x = 0; x < 50; ++x) {
            const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
            const glm::vec3 origin(ray.origin), direction(ray.direction);
            if (fixture.scene->bvh().intersect(origin, direction).hit()) continue;
            glm::vec3 seed;
            float distance, bottom = 0.0f;
            const bool found = findClosestApproach(sampler, origin, direction, 0.4f, box, seed, distance, &bottom);
            float tEnter, tExit;
            if (!core::rayBoxInterval(origin, direction, box, tEnter, tExit)) continue;
            approached += found;
            const float middle = 0.5f * (tEnter + tExit);
            for (const float hint : {bottom, bottom + 3.0f * voxel, bottom - 3.0f * voxel, middle}) {
                glm::vec3 hintedSeed;
                float hintedDistance;
                const bool hintedFound = findClosestApproachHinted(sampler, origin, direction, 0.4f, box, hint, voxel,
                                                                   hintedSeed, hintedDistance);
                ASSERT_EQ(hintedFound, found) << x << ", " << y << " hint " << hint;
                if (!found) continue;
                hintedElsewhere += std::abs(hint - bottom) > 10.0f * voxel;
                EXPECT_LT(glm::length(hintedSeed - seed), 0.01f * voxel) << x << ", " << y << " hint " << hint;
                EXPECT_NEAR(hintedDistance, distance, 0.01f * voxel) << x << ", " << y << " hint " << hint;
            }
        }
    EXPECT_GT(approached, 300);
    EXPECT_GT(hintedElsewhere, 50) << "some hints must lie far from the ray's lowest valley";
}

TEST(CurvedRay, ClosestApproachTakesTheMiddleOfAFlatValley)
{
    // A box 2 long in z, 1 wide in x, 0.4 high in y, built as the volumes of the programs are.
    core::SurfaceField box;
    const glm::vec3 half(0.5f, 0.2f, 1.0f);
    for (int i = 0; i < 8; ++i)
        box.mesh.positions.push_back({(i & 1 ? 1 : -1) * half.x, (i & 2 ? 1 : -1) * half.y, (i & 4 ? 1 : -1) * half.z});
    // Two outward-wound triangles per face (corner index bits: x 1, y 2, z 4).
    const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& f : faces) {
        box.mesh.triangles.push_back({f[0], f[1], f[2]});
        box.mesh.triangles.push_back({f[0], f[2], f[3]});
    }
    box.mesh.dataTriangleCount = box.mesh.triangles.size();
    const test::SceneFixture fixture(std::move(box), 100);
    auto sampler = fixture.scene->distance().sampler();
    const float voxel = fixture.scene->distance().voxelSize();
    const core::Bounds3 hull = hullBounds(fixture.scene->bounds(), 0.4f, voxel);
    for (float y = -0.1f; y <= 0.1f; y += 0.01f)
        for (const float height : {0.05f, 0.1371f, 0.2f}) {
            // Along -z, at a constant height above the +x face.
            const glm::vec3 origin(half.x + height, y, 3.0f), direction(0.0f, 0.0f, -1.0f);
            glm::vec3 seed;
            float distance;
            ASSERT_TRUE(findClosestApproach(sampler, origin, direction, 0.4f, hull, seed, distance)) << y;
            EXPECT_NEAR(distance, height, 0.25f * voxel) << y << " " << height;
            EXPECT_NEAR(seed.z, 0.0f, voxel) << y << " " << height;
        }
}

TEST(CurvedRay, SmallAlphaFallsRadiallyFromTheSeed)
{
    std::vector<glm::vec3> seeds;
    const std::vector<CurvedRayEnd> ends = sweep(0.001f, &seeds);
    ASSERT_GT(ends.size(), 50u);
    float zMin = 1.0f, zMax = -1.0f;
    for (std::size_t i = 0; i < ends.size(); ++i) {
        ASSERT_TRUE(ends[i].landed);
        EXPECT_LT(glm::length(ends[i].position - glm::normalize(seeds[i])), 0.02f);
        zMin = std::min(zMin, ends[i].position.z);
        zMax = std::max(zMax, ends[i].position.z);
    }
    // docs/method.md: alpha ~ 0 lands on the band -0.35 .. 0.52.
    EXPECT_NEAR(zMin, -0.35f, 0.05f);
    EXPECT_NEAR(zMax, 0.52f, 0.05f);
}

TEST(CurvedRay, LargerAlphaLandsDeeperOnTheBack)
{
    float previousMeanZ = 1.0f;
    for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f}) {
        const std::vector<CurvedRayEnd> ends = sweep(alpha);
        double sumZ = 0.0;
        int landed = 0;
        for (const CurvedRayEnd& end : ends)
            if (end.landed) {
                sumZ += end.position.z;
                ++landed;
                // Landed means phi < eps = half a voxel (0.0125 here), up to interpolation error.
                EXPECT_NEAR(glm::length(end.position), 1.0f, 0.0125f + 0.002f);
            }
        ASSERT_GT(landed, 50);
        const float meanZ = float(sumZ / landed);
        EXPECT_LT(meanZ, previousMeanZ) << "alpha " << alpha;
        previousMeanZ = meanZ;
    }
}

TEST(CurvedRay, OneSymplecticEulerStepMatchesTheFormula)
{
    const auto& fixture = test::sphereScene();
    auto sampler = fixture.scene->distance().sampler();
    const glm::vec3 p0(0.3f, -0.9f, -0.8f), v0(0.2f, 0.1f, -0.4f);
    CurvedRayParams params;
    params.maxSteps = 1;
    const CurvedRayEnd end = traceCurvedRay(sampler, p0, v0, params, 1e-6f);
    glm::vec3 gradient;
    const float phi = sampler.phiAndGradient(p0, gradient);
    const glm::vec3 v1 = v0 - params.stepSize * gradient;
    const glm::vec3 p1 = p0 + params.stepSize * phi * v1 / glm::length(v1);
    EXPECT_EQ(end.steps, 1);
    EXPECT_FALSE(end.landed);
    EXPECT_LT(glm::length(end.velocity - v1), 1e-6f);
    EXPECT_LT(glm::length(end.position - p1), 1e-6f);
    // On the unit sphere phi = |p| - 1 and grad phi = p / |p|.
    EXPECT_NEAR(phi, glm::length(p0) - 1.0f, 0.5f * fixture.scene->distance().voxelSize());
    EXPECT_LT(glm::length(gradient - glm::normalize(p0)), 0.02f);
}

TEST(CurvedRay, InitialVelocityIsTangentialToTheHull)
{
    const glm::vec3 g = glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f));
    const glm::vec3 r = glm::normalize(glm::vec3(0.1f, -0.3f, -1.0f));
    const glm::vec3 v = initialVelocity(2.0f * g, r, 0.5f);
    EXPECT_NEAR(glm::dot(v, g), 0.0f, 1e-6f);
    EXPECT_LT(glm::length(v - 0.5f * (r - glm::dot(r, g) * g)), 1e-6f);
}

}  // namespace
}  // namespace ivis::render
