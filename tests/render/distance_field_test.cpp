// DistanceField::Sampler on a unit sphere (fine band at resolution 100, far field at 40): phi and
// its gradient against the exact sphere distance |p| - 1, the gradient against the blend of the
// brute-force gradients at the cell's corners and across voxel faces, the nearest triangle against
// a brute-force search, the samples once the volume has released the grids the field copied, the
// Hessian against the sphere's (I - n n^T) / |p|, and detail::blend against its formula bit for bit.
#include "brute_force.h"
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/core/closest_point.h>
#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/render/distance_field.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace ivis::render {
namespace {

/// Unit sphere (subdivision 4, within 4e-4 of the sphere), its band and its far field.
const test::SceneFixture& sphere() { return test::sphereWithFarField(); }

double angleDeg(const glm::vec3& a, const glm::vec3& b)
{
    return glm::degrees(std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)));
}

TEST(DistanceField, PhiAndGradientMatchTheSphereInTheBandAndTheFarField)
{
    const DistanceField field(sphere().volume);
    ASSERT_TRUE(sphere().volume.farPhi) << "the far field must exist for this test";
    auto sampler = field.sampler();
    const float fine = field.voxelSize(), far = float(sphere().volume.farLattice().voxelSize());
    // Radii inside the band (|phi| < 2 fine voxels) and in the far field (0.25 to 0.55 outside).
    for (const auto& [radius, tolerance, angleTolerance] :
         {std::tuple{0.92f, 0.1f * fine, 3.0}, {1.0f, 0.1f * fine, 3.0}, {1.07f, 0.1f * fine, 3.0},
          {1.25f, 0.1f * far, 6.0}, {1.55f, 0.1f * far, 6.0}}) {
        for (const glm::vec3& n : test::fibonacciDirections(200)) {
            const glm::vec3 p = radius * n;
            glm::vec3 gradient;
            const float phi = sampler.phiAndGradient(p, gradient);
            EXPECT_NEAR(phi, radius - 1.0f, tolerance) << "at radius " << radius;
            EXPECT_FLOAT_EQ(sampler.phi(p), phi);
            EXPECT_LT(angleDeg(gradient, n), angleTolerance) << "at radius " << radius;
            EXPECT_NEAR(glm::length(gradient), 1.0f, 0.05f) << "at radius " << radius;
        }
    }
}

TEST(DistanceField, SamplesTheSameOnceItsVolumeReleasesTheGridsItCopied)
{
    // With a far field (the band in bricks) and without (phi itself is the dense copy).
    for (const test::SceneFixture* fixture : {&sphere(), &test::sphereScene()}) {
        vdb::SurfaceVolume volume = fixture->volume;  // shares the grids; releasing resets this copy's
        const DistanceField field(volume);
        const double reach = volume.reach();
        const std::size_t bytes = volume.memoryBytes();
        auto sampleAll = [&] {
            auto sampler = field.sampler();
            std::vector<float> values;
            for (const float radius : {0.95f, 1.0f, 1.04f, 1.3f, 1.8f})
                for (const glm::vec3& n : test::fibonacciDirections(100)) {
                    glm::vec3 gradient;
                    values.push_back(sampler.phiAndGradient(radius * n, gradient));
                    values.insert(values.end(), {gradient.x, gradient.y, gradient.z});
                    values.push_back(float(sampler.nearestTriangle(radius * n)));
                }
            return values;
        };
        const std::vector<float> before = sampleAll();
        volume.releaseSampledGrids();
        EXPECT_TRUE(volume.released());
        EXPECT_EQ(sampleAll(), before);  // bit for bit
        EXPECT_EQ(volume.reach(), reach);
        EXPECT_LT(volume.memoryBytes(), bytes / 2);
        EXPECT_THROW(DistanceField{volume}, InternalError);
        EXPECT_FALSE(fixture->volume.released());
    }
}

TEST(DistanceField, GradientIsTheTrilinearBlendOfTheExactCornerGradients)
{
    const DistanceField field(sphere().volume);
    auto sampler = field.sampler();
    const test::BruteForceClosest brute(sphere().field.mesh);
    const vdb::BoxLattice fineLattice = sphere().volume.lattice(), farLattice = sphere().volume.farLattice();
    // In the band (radius 1.02) and in the far field (1.4), at points off the voxel centres.
    for (const auto& [radius, lattice] : {std::pair{1.02, fineLattice}, {1.4, farLattice}}) {
        for (const glm::vec3& n : test::fibonacciDirections(50)) {
            const glm::dvec3 p = radius * glm::dvec3(n);
            glm::dvec3 cell, t;
            for (int a = 0; a < 3; ++a) {
                cell[a] = std::floor(lattice.indexFromWorld(p[a]));
                t[a] = lattice.indexFromWorld(p[a]) - cell[a];
            }
            glm::dvec3 expected(0.0);
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 corner(i & 1, (i >> 1) & 1, (i >> 2) & 1);
                glm::dvec3 x;
                for (int a = 0; a < 3; ++a) x[a] = lattice.worldFromIndex(cell[a] + corner[a]);
                const glm::dvec3 w = glm::mix(glm::dvec3(1.0) - t, t, corner);
                expected += w.x * w.y * w.z * brute.distanceGradient(x);
            }
            glm::vec3 gradient;
            sampler.phiAndGradient(glm::vec3(p), gradient);
            EXPECT_LT(glm::length(glm::dvec3(gradient) - expected), 1e-4) << "at radius " << radius;
        }
    }
}

TEST(DistanceField, GradientIsContinuousAcrossVoxelFaces)
{
    const DistanceField field(sphere().volume);
    auto sampler = field.sampler();
    const vdb::BoxLattice fineLattice = sphere().volume.lattice(), farLattice = sphere().volume.farLattice();
    // The gradient of a trilinear phi jumps by up to h / radius across a face; the blend does not.
    for (const auto& [radius, lattice] : {std::pair{1.02, fineLattice}, {1.4, farLattice}}) {
        const double side = 1e-4 * lattice.voxelSize();
        for (const glm::vec3& n : test::fibonacciDirections(50)) {
            for (int a = 0; a < 3; ++a) {
                glm::dvec3 p = radius * glm::dvec3(n);
                p[a] = lattice.worldFromIndex(std::floor(lattice.indexFromWorld(p[a])));  // on a face
                glm::dvec3 before = p, after = p;
                before[a] -= side;
                after[a] += side;
                glm::vec3 g0, g1;
                sampler.phiAndGradient(glm::vec3(before), g0);
                sampler.phiAndGradient(glm::vec3(after), g1);
                EXPECT_LT(glm::length(g1 - g0), 1e-3) << "axis " << a << " at radius " << radius;
            }
        }
    }
}

// Within a far voxel of the surface the far field's blend is poor (its corners straddle the
// surface), so the band reaches beyond it, and the sampler passes from band to far field across
// [fineFrom, fineUntil] instead of at the band's voxel-shaped edge: along radial lines through the
// passage, phi and its gradient change by no more per step than the smooth field does.
TEST(DistanceField, PhiAndGradientPassFromTheBandToTheFarFieldContinuously)
{
    const DistanceField field(sphere().volume);
    auto sampler = field.sampler();
    const float fine = field.voxelSize(), far = float(sphere().volume.farLattice().voxelSize());
    EXPECT_GE(field.fineFrom(), 0.5f * far);
    EXPECT_GT(field.fineUntil(), field.fineFrom());
    const float step = 0.002f * fine;
    float worstPhi = 0.0f, worstGradient = 0.0f;
    for (const glm::vec3& n : test::fibonacciDirections(100)) {
        glm::vec3 previousGradient;
        float previousPhi = sampler.phiAndGradient((1.0f + 0.5f * field.fineFrom()) * n, previousGradient);
        for (float d = 0.5f * field.fineFrom() + step; d < 1.5f * field.fineUntil(); d += step) {
            glm::vec3 gradient;
            const float phi = sampler.phiAndGradient((1.0f + d) * n, gradient);
            worstPhi = std::max(worstPhi, std::abs(phi - previousPhi - step));
            worstGradient = std::max(worstGradient, glm::length(gradient - previousGradient));
            previousPhi = phi;
            previousGradient = gradient;
        }
    }
    // A step moves phi by the step and the sphere's gradient by step / radius; the blend adds a
    // share of the small band-to-far difference per step.
    EXPECT_LT(worstPhi, 0.1f * step) << "largest change of phi per step beyond the step itself";
    EXPECT_LT(worstGradient, 20.0f * step) << "largest change of the gradient per step";
    std::cout << "[ passage  ] per step of " << step << ": phi " << worstPhi << ", gradient " << worstGradient << "\n";
}

TEST(DistanceField, NearestTriangleIsTheBruteForceClosestAtVoxelCentres)
{
    const vdb::SurfaceVolume& volume = sphere().volume;
    const DistanceField field(volume);
    auto sampler = field.sampler();
    const test::BruteForceClosest brute(sphere().field.mesh);
    const vdb::BoxLattice lattice = volume.lattice();
    int checked = 0;
    for (auto voxel = volume.phi->cbeginValueOn(); voxel; ++voxel) {
        if (voxel.getCoord().x() % 3 != 0) continue;  // a third of the band keeps the test fast
        const openvdb::Vec3d centre = lattice.worldFromIndex(voxel.getCoord());
        const glm::vec3 p(float(centre.x()), float(centre.y()), float(centre.z()));
        const int triangle = sampler.nearestTriangle(p);
        ASSERT_GE(triangle, 0);
        std::int32_t expected = -1;
        const double best = std::sqrt(brute.closest(glm::dvec3(p), &expected).distanceSquared);
        if (triangle == expected) { ++checked; continue; }
        // A tie (shared edge or vertex): the stored triangle must be as close.
        const auto& t = sphere().field.mesh.triangles[std::size_t(triangle)];
        const glm::dvec3 a(sphere().field.mesh.positions[t[0]]), b(sphere().field.mesh.positions[t[1]]),
            c(sphere().field.mesh.positions[t[2]]);
        EXPECT_NEAR(std::sqrt(core::closestPointOnTriangle(glm::dvec3(p), a, b, c).distanceSquared), best, 1e-6);
        ++checked;
    }
    EXPECT_GT(checked, 1000);
}

// detail::blend (four components in one SSE register where there is SSE2) gives the bits of its
// formula written out one component at a time: sum_i w_i c_i, then phi += h (sum g . t - sum_i w_i
// g_i . d_i), each sum in corner order; zero gradient components of either sign and a NaN corner
// (outside the band) included.
TEST(DistanceField, BlendGivesTheBitsOfItsFormula)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), signedUnit(-1.0f, 1.0f);
    for (int item = 0; item < 20000; ++item) {
        glm::vec4 c[8];
        for (glm::vec4& corner : c)
            corner = glm::vec4(0.05f * signedUnit(random), signedUnit(random), signedUnit(random), signedUnit(random));
        if (item % 7 == 0) c[item % 8].z = item % 2 ? 0.0f : -0.0f;
        if (item % 101 == 0) c[item % 8].x = std::numeric_limits<float>::quiet_NaN();
        const glm::vec3 t(unit(random), unit(random), unit(random));
        const float h = 0.01f * (1.0f + unit(random));
        float w[8];
        detail::trilinearWeights(t, w);
        // The corners summed in pairs, the pairs' sums in pairs (component by component), and each
        // corner's g . d, d its offset in the cell, as detail::blendCorners writes them.
        float sum[4];
        for (int k = 0; k < 4; ++k)
            sum[k] = ((w[0] * c[0][k] + w[1] * c[1][k]) + (w[2] * c[2][k] + w[3] * c[3][k])) +
                     ((w[4] * c[4][k] + w[5] * c[5][k]) + (w[6] * c[6][k] + w[7] * c[7][k]));
        const float towards =
            ((w[1] * c[1].y + w[2] * c[2].z) + (w[3] * (c[3].y + c[3].z) + w[4] * c[4].w)) +
            ((w[5] * (c[5].y + c[5].w) + w[6] * (c[6].z + c[6].w)) + w[7] * ((c[7].y + c[7].z) + c[7].w));
        sum[0] += h * (sum[1] * t.x + sum[2] * t.y + sum[3] * t.z - towards);
        const glm::vec4 blended = detail::blend(c, t, h);
        if (std::isnan(sum[0])) {
            EXPECT_TRUE(std::isnan(blended.x)) << "item " << item;
            continue;
        }
        ASSERT_EQ(std::memcmp(&blended.x, sum, sizeof sum), 0)
            << "item " << item << ": (" << blended.x << ", " << blended.y << ", " << blended.z << ", " << blended.w
            << ") against (" << sum[0] << ", " << sum[1] << ", " << sum[2] << ", " << sum[3] << ")";
    }
}

}  // namespace
}  // namespace ivis::render
