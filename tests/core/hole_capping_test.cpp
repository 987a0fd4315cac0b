#include <ivis/core/hole_capping.h>
#include <ivis/core/mesh_reader.h>

#include "test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace ivis::core {
namespace {

/// test::openTube as a field, every triangle flipped (facing inward) if @a inward.
SurfaceField openTube(std::uint32_t n, bool inward = false)
{
    SurfaceField field;
    field.mesh = test::openTube(n);
    if (inward) {
        for (auto& t : field.mesh.triangles) std::swap(t[1], t[2]);
    }
    return field;
}

/// Sum of signed tetrahedron volumes against the origin: the enclosed volume, positive when the
/// closed mesh faces outward.
double signedVolume(const TriangleMesh& mesh)
{
    double volume = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

/// True when every directed edge occurs once and its reverse occurs once (closed, consistently
/// oriented).
bool consistentlyClosed(const TriangleMesh& mesh)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) return false;
    }
    return true;
}

TEST(HoleCapping, CappingATubeClosesIt)
{
    const std::uint32_t n = 8;
    SurfaceField tube = openTube(n);
    ASSERT_EQ(boundaryEdgeCount(tube.mesh), 2 * n);

    EXPECT_EQ(capHoles(tube), 2u);
    const TriangleMesh& mesh = tube.mesh;
    EXPECT_EQ(boundaryEdgeCount(mesh), 0u);
    EXPECT_EQ(mesh.dataTriangleCount, 2 * n);
    ASSERT_EQ(mesh.triangles.size(), 4 * n);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) EXPECT_EQ(mesh.isCap(t), t >= 2 * n);

    // One centroid vertex per rim, at the rim centres.
    ASSERT_EQ(mesh.positions.size(), 2 * n + 2);
    const glm::vec3 c0 = mesh.positions[2 * n], c1 = mesh.positions[2 * n + 1];
    EXPECT_NEAR(std::hypot(c0.x, c0.y), 0.0, 1e-6);
    EXPECT_NEAR(std::hypot(c1.x, c1.y), 0.0, 1e-6);
    EXPECT_NEAR(std::min(c0.z, c1.z), 0.0, 1e-6);
    EXPECT_NEAR(std::max(c0.z, c1.z), 1.0, 1e-6);
}

TEST(HoleCapping, CapsFollowTheOrientationOfTheirNeighbours)
{
    // Regular n-gon prism of height 1: volume = n/2 sin(2 pi / n).
    const std::uint32_t n = 8;
    const double prism = 0.5 * n * std::sin(2.0 * glm::pi<double>() / n);
    for (const bool inward : {false, true}) {
        SurfaceField tube = openTube(n, inward);
        capHoles(tube);
        EXPECT_TRUE(consistentlyClosed(tube.mesh)) << (inward ? "inward" : "outward");
        EXPECT_NEAR(signedVolume(tube.mesh), inward ? -prism : prism, 1e-5);
    }
}

TEST(HoleCapping, NewVerticesGetNanScalar)
{
    SurfaceField tube = openTube(6);
    tube.values.assign(tube.mesh.positions.size(), 1.0f);
    tube.name = "wss";
    capHoles(tube);
    ASSERT_EQ(tube.values.size(), tube.mesh.positions.size());
    for (std::size_t v = 0; v < 12; ++v) EXPECT_EQ(tube.values[v], 1.0f);
    EXPECT_TRUE(std::isnan(tube.values[12]));
    EXPECT_TRUE(std::isnan(tube.values[13]));

    SurfaceField bare = openTube(6);
    capHoles(bare);
    EXPECT_FALSE(bare.hasScalar());
}

TEST(HoleCapping, ClosedMeshIsUnchanged)
{
    SurfaceField tube = openTube(5);
    capHoles(tube);
    const TriangleMesh before = tube.mesh;
    EXPECT_EQ(capHoles(tube), 0u);
    EXPECT_EQ(tube.mesh.triangles, before.triangles);
    EXPECT_EQ(tube.mesh.positions.size(), before.positions.size());
}

TEST(HoleCapping, CappingTheOpenLeftAtriumClosesIt)
{
    SurfaceField atrium = readMesh(test::sharedMesh("lasc2013_b003_left_atrium.ply"));
    ASSERT_EQ(boundaryEdgeCount(atrium.mesh), 462u);
    const std::size_t dataTriangles = atrium.mesh.triangles.size();
    const std::size_t loops = boundaryLoops(atrium.mesh).size();
    EXPECT_EQ(capHoles(atrium), loops);
    EXPECT_EQ(boundaryEdgeCount(atrium.mesh), 0u);
    EXPECT_EQ(atrium.mesh.dataTriangleCount, dataTriangles);
    EXPECT_EQ(atrium.mesh.triangles.size(), dataTriangles + 462);  // one cap triangle per rim edge
    EXPECT_EQ(componentCount(atrium.mesh), 1u);
}

}  // namespace
}  // namespace ivis::core
