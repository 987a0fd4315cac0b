#include <ivis/core/errors.h>
#include <ivis/core/triangle_mesh.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>

namespace ivis::core {
namespace {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

EdgeKey key(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

using test::openTube;

/// Closed tetrahedron, outward-facing: 0 at the origin, 1 on x, 2 on y, 3 on z.
TriangleMesh tetrahedron()
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    mesh.dataTriangleCount = 4;
    return mesh;
}

/// Edges used by exactly one triangle, counted by brute force.
std::map<EdgeKey, int> bruteBoundary(const TriangleMesh& mesh)
{
    std::map<EdgeKey, int> uses;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) ++uses[key(t[k], t[(k + 1) % 3])];
    }
    std::map<EdgeKey, int> boundary;
    for (const auto& [edge, count] : uses) {
        if (count == 1) boundary[edge] = 0;
    }
    return boundary;
}

/// Every boundary edge must be walked by exactly one loop (consecutive vertices, plus the closing
/// pair when that is a boundary edge).
void expectLoopsCoverBoundaryOnce(const TriangleMesh& mesh)
{
    std::map<EdgeKey, int> boundary = bruteBoundary(mesh);
    for (const auto& loop : boundaryLoops(mesh)) {
        ASSERT_GE(loop.size(), 2u);
        for (std::size_t i = 0; i + 1 < loop.size(); ++i) {
            const auto it = boundary.find(key(loop[i], loop[i + 1]));
            ASSERT_NE(it, boundary.end()) << "loop step is not a boundary edge";
            ++it->second;
        }
        const auto closing = boundary.find(key(loop.back(), loop.front()));
        if (loop.size() > 2 && closing != boundary.end() && closing->second == 0) ++closing->second;
    }
    for (const auto& [edge, walked] : boundary) {
        EXPECT_EQ(walked, 1) << "edge " << edge.first << "-" << edge.second;
    }
}

TEST(TriangleMesh, BoundsOfTetrahedron)
{
    const Bounds3 b = bounds(tetrahedron());
    EXPECT_EQ(b.lo, glm::dvec3(0.0));
    EXPECT_EQ(b.hi, glm::dvec3(1.0));
}

TEST(TriangleMesh, BoundsOfEmptyMeshThrows) { EXPECT_THROW(bounds(TriangleMesh{}), ValueError); }

TEST(TriangleMesh, OpenTubeHasTwoBoundaryLoops)
{
    const TriangleMesh tube = openTube(6);
    EXPECT_EQ(boundaryEdgeCount(tube), 12u);
    EXPECT_EQ(componentCount(tube), 1u);
    const auto loops = boundaryLoops(tube);
    ASSERT_EQ(loops.size(), 2u);
    for (const auto& loop : loops) {
        ASSERT_EQ(loop.size(), 6u);
        const bool bottom = loop.front() < 6;
        for (std::uint32_t v : loop) EXPECT_EQ(v < 6, bottom) << "a loop mixes the two rims";
    }
    expectLoopsCoverBoundaryOnce(tube);
}

TEST(TriangleMesh, LoopsFollowTriangleOrientation)
{
    // Bottom rim edges run i -> i+1 in the triangles, so the bottom loop must too.
    const auto loops = boundaryLoops(openTube(5));
    int bottomLoops = 0;
    for (const auto& loop : loops) {
        if (loop.front() >= 5) continue;
        ++bottomLoops;
        ASSERT_EQ(loop.size(), 5u);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            EXPECT_EQ(loop[(i + 1) % loop.size()], (loop[i] + 1) % 5);
        }
    }
    EXPECT_EQ(bottomLoops, 1);
}

TEST(TriangleMesh, ClosedTetrahedronHasNoBoundary)
{
    const TriangleMesh tet = tetrahedron();
    EXPECT_EQ(boundaryEdgeCount(tet), 0u);
    EXPECT_EQ(componentCount(tet), 1u);
    EXPECT_TRUE(boundaryLoops(tet).empty());
}

TEST(TriangleMesh, TwoDisjointTriangles)
{
    //   2        5
    //   | \      | \      (second triangle shifted by 5 on x)
    //   0--1     3--4
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(boundaryEdgeCount(mesh), 6u);
    EXPECT_EQ(componentCount(mesh), 2u);
    const auto loops = boundaryLoops(mesh);
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(loops[0].size(), 3u);
    EXPECT_EQ(loops[1].size(), 3u);
    expectLoopsCoverBoundaryOnce(mesh);
}

TEST(TriangleMesh, IsolatedVerticesAreNotComponents)
{
    TriangleMesh mesh = tetrahedron();
    mesh.positions.emplace_back(9, 9, 9);
    EXPECT_EQ(componentCount(mesh), 1u);
}

TEST(TriangleMesh, ThreeTrianglesOnOneEdge)
{
    // Edge 0-1 is shared by three fins (non-manifold); 0 and 1 each touch three boundary edges.
    //        2
    //       /|
    //  3 - 0-+-1 - 4   (fins 2, 3, 4 around the edge 0-1)
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    EXPECT_EQ(boundaryEdgeCount(mesh), 6u);
    EXPECT_EQ(componentCount(mesh), 1u);
    expectLoopsCoverBoundaryOnce(mesh);
}

TEST(TriangleMesh, BowtieSplitsIntoTwoLoops)
{
    // Two triangles touching at vertex 0 only: 0 has four boundary edges.
    //  2         4
    //  | \     / |
    //  1 - 0 - 3
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {-1, 0, 0}, {-1, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 2, 1}, {0, 3, 4}};
    EXPECT_EQ(boundaryEdgeCount(mesh), 6u);
    EXPECT_EQ(componentCount(mesh), 1u);
    const auto loops = boundaryLoops(mesh);
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(loops[0].size(), 3u);
    EXPECT_EQ(loops[1].size(), 3u);
    expectLoopsCoverBoundaryOnce(mesh);
}

TEST(TriangleMesh, InconsistentOrientationStillFormsOneLoop)
{
    // A strip of two triangles where the second is flipped: the rim 0-1-2-3 is one loop.
    //  3 --- 2
    //  |  /  |
    //  0 --- 1
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    std::swap(mesh.triangles[1][1], mesh.triangles[1][2]);
    const auto loops = boundaryLoops(mesh);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_EQ(loops[0].size(), 4u);
    expectLoopsCoverBoundaryOnce(mesh);
}

// Random soups over few vertices (edges used once, twice, thrice and more, in either direction,
// triangles with a repeated vertex): as many boundary edges as brute force counts.
TEST(TriangleMesh, BoundaryOfRandomSoupsMatchesBruteForce)
{
    std::mt19937 random(5);
    for (int trial = 0; trial < 20; ++trial) {
        TriangleMesh mesh;
        const std::uint32_t vertices = 4 + std::uint32_t(trial) * 3;
        mesh.positions.assign(vertices, glm::vec3(0.0f));
        std::uniform_int_distribution<std::uint32_t> vertex(0, vertices - 1);
        for (int t = 0; t < 10 + 15 * trial; ++t) mesh.triangles.push_back({vertex(random), vertex(random), vertex(random)});
        std::size_t expected = 0;
        for (const auto& [edge, walked] : bruteBoundary(mesh)) expected += edge.first != edge.second ? 1 : 0;
        EXPECT_EQ(boundaryEdgeCount(mesh), expected) << "trial " << trial;
    }
}

TEST(TriangleMesh, TwoTetrahedraSharingAVertex)
{
    TriangleMesh mesh = tetrahedron();
    for (auto p : tetrahedron().positions) mesh.positions.push_back(-p);
    for (auto t : tetrahedron().triangles) {
        for (auto& v : t) v = v == 0 ? 0 : v + 4;  // second copy shares vertex 0
        mesh.triangles.push_back(t);
    }
    EXPECT_EQ(boundaryEdgeCount(mesh), 0u);
    EXPECT_EQ(componentCount(mesh), 1u);
    EXPECT_TRUE(boundaryLoops(mesh).empty());
}

}  // namespace
}  // namespace ivis::core
