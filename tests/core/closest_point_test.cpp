// The closest point on a triangle four at a time (closestPointsOnTriangles) against the scalar
// function bit for bit, over every Voronoi region and degenerate triangles; and the BVH's bounded
// query, which tests its visited triangles together, against brute force.
#include "brute_force.h"

#include <ivis/core/closest_point.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/triangle_bvh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace ivis::core {
namespace {

bool sameBits(const TrianglePoint& a, const TrianglePoint& b)
{
    return std::memcmp(&a.point, &b.point, sizeof a.point) == 0 &&
           std::memcmp(&a.barycentric, &b.barycentric, sizeof a.barycentric) == 0 &&
           std::memcmp(&a.distanceSquared, &b.distanceSquared, sizeof a.distanceSquared) == 0;
}

/// Which of the seven answers closestPointOnTriangle gave: a vertex (0-2), an edge (3-5) or the face (6).
int regionOf(const TrianglePoint& t)
{
    const glm::dvec3& w = t.barycentric;
    const int zeros = (w.x == 0.0) + (w.y == 0.0) + (w.z == 0.0);
    if (zeros == 2) return w.x == 1.0 ? 0 : w.y == 1.0 ? 1 : 2;
    if (zeros == 1) return w.z == 0.0 ? 3 : w.y == 0.0 ? 4 : 5;
    return 6;
}

TEST(ClosestPointsOnTriangles, AreTheScalarFunctionsBitsInEveryRegionAndOnDegenerateTriangles)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto point = [&] { return glm::dvec3(unit(random), unit(random), unit(random)); };
    std::set<int> regions;
    int degenerate = 0;
    for (int round = 0; round < 4000; ++round) {
        const int count = 1 + round % 11;  // whole fours and remainders
        std::vector<glm::dvec3> corners;
        for (int k = 0; k < count; ++k) {
            glm::dvec3 a = point(), b = point(), c = point();
            switch ((round + k) % 7) {
            case 0: c = a + 0.37 * (b - a), ++degenerate; break;  // collinear
            case 1: b = a, ++degenerate; break;                   // a repeated corner
            case 2: b = a, c = a, ++degenerate; break;            // a point
            case 3: b = a + 1e-9 * (b - a), c = a + 1e-9 * (c - a); break;  // tiny
            default: break;
            }
            // Triangles given as the floats a mesh stores, as the BVH gives them.
            for (const glm::dvec3& v : {a, b, c}) corners.push_back(glm::dvec3(glm::vec3(v)));
        }
        const glm::dvec3 p = 1.5 * point();
        std::vector<TrianglePoint> together(static_cast<std::size_t>(count));
        closestPointsOnTriangles(p, corners.data(), count, together.data());
        for (int k = 0; k < count; ++k) {
            const TrianglePoint alone = closestPointOnTriangle(p, corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]);
            ASSERT_TRUE(sameBits(together[std::size_t(k)], alone)) << "round " << round << ", triangle " << k;
            regions.insert(regionOf(alone));
        }
    }
    EXPECT_EQ(regions.size(), 7u);  // every vertex, every edge and the face answered somewhere
    EXPECT_GT(degenerate, 1000);
}

TEST(TriangleBvh, BoundedClosestPointIsTheBruteForcesLeastDistanceAndLowestIndex)
{
    const SurfaceField sphere = makeSphere(3);
    const TriangleMesh& mesh = sphere.mesh;
    const TriangleBvh bvh(mesh);
    const test::BruteForceClosest brute(mesh);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.6, 1.6);
    for (int i = 0; i < 400; ++i) {
        // Points on the vertices (equal distances to several triangles) as well as anywhere.
        const glm::dvec3 p = i % 5 == 0 ? glm::dvec3(mesh.positions[std::size_t(i) % mesh.positions.size()])
                                        : glm::dvec3(unit(random), unit(random), unit(random));
        std::int32_t expected = -1;
        const TrianglePoint truth = brute.closest(p, &expected);
        for (const double radius : {std::sqrt(truth.distanceSquared) * 1.001 + 1e-9,
                                    std::numeric_limits<double>::infinity()}) {
            int triangle = -2;
            const TrianglePoint found = bvh.closestPoint(p, radius, triangle);
            ASSERT_EQ(triangle, expected) << "point " << i << ", radius " << radius;
            ASSERT_TRUE(sameBits(found, truth)) << "point " << i;
        }
        if (truth.distanceSquared > 1e-2) {  // nothing within half the distance
            int none = -2;
            bvh.closestPoint(p, 0.5 * std::sqrt(truth.distanceSquared), none);
            EXPECT_EQ(none, -1) << "point " << i;
        }
    }
}

}  // namespace
}  // namespace ivis::core
