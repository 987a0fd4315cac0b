#include <ivis/core/errors.h>
#include <ivis/core/marching_tetrahedra.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <tbb/task_arena.h>

#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace ivis::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

double signedVolume(const TriangleMesh& mesh)
{
    auto at = [&](std::uint32_t v) { return glm::dvec3(mesh.positions[v]); };
    double volume = 0.0;
    for (const auto& [a, b, c] : mesh.triangles)
        volume += glm::dot(at(a), glm::cross(at(b), at(c)));
    return volume / 6.0;
}

std::size_t edgeCount(const TriangleMesh& mesh)
{
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : mesh.triangles)
        for (int i = 0; i < 3; ++i)
            edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
    return edges.size();
}

const Bounds3 kUnitBox{glm::dvec3(-1.0), glm::dvec3(1.0)};

double sphereOfRadius07(const glm::dvec3& p) { return glm::length(p) - 0.7; }

TEST(MarchingTetrahedra, SphereVerticesWithinHalfACellOfTheRadius)
{
    const double cell = 0.05;
    const TriangleMesh mesh = marchingTetrahedra(sphereOfRadius07, kUnitBox, cell);
    ASSERT_GT(mesh.triangles.size(), 1000u);
    EXPECT_EQ(mesh.dataTriangleCount, mesh.triangles.size());
    for (const glm::vec3& p : mesh.positions)
        ASSERT_LT(std::abs(glm::length(glm::dvec3(p)) - 0.7), 0.5 * cell);
}

TEST(MarchingTetrahedra, SphereIsClosedOutwardGenusZero)
{
    const TriangleMesh mesh = marchingTetrahedra(sphereOfRadius07, kUnitBox, 0.05);
    EXPECT_EQ(boundaryEdgeCount(mesh), 0u);
    EXPECT_EQ(componentCount(mesh), 1u);
    const long euler = long(mesh.positions.size()) - long(edgeCount(mesh)) +
                       long(mesh.triangles.size());
    EXPECT_EQ(euler, 2);
    const double exact = 4.0 / 3.0 * kPi * 0.7 * 0.7 * 0.7;
    EXPECT_NEAR(signedVolume(mesh), exact, 0.03 * exact);  // positive: outward
}

TEST(MarchingTetrahedra, NoDegenerateTriangles)
{
    const TriangleMesh mesh = marchingTetrahedra(sphereOfRadius07, kUnitBox, 0.07);
    ASSERT_FALSE(mesh.triangles.empty());
    for (const auto& [a, b, c] : mesh.triangles) {
        const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
        ASSERT_GT(glm::length(glm::cross(pb - pa, pc - pa)), 0.0);
    }
}

TEST(MarchingTetrahedra, PlaneIsExactAndFacesPositiveSide)
{
    // f = z - 0.013 is linear, so interpolated vertices lie exactly on the plane; the outside
    // (f > 0) is +z, so every normal points up. The plane leaves the box: the mesh is open.
    const TriangleMesh mesh =
        marchingTetrahedra([](const glm::dvec3& p) { return p.z - 0.013; }, kUnitBox, 0.1);
    ASSERT_FALSE(mesh.triangles.empty());
    for (const glm::vec3& p : mesh.positions) EXPECT_NEAR(p.z, 0.013, 1e-6);
    for (const auto& [a, b, c] : mesh.triangles) {
        const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b] - mesh.positions[a]),
                                        glm::dvec3(mesh.positions[c] - mesh.positions[a]));
        ASSERT_GT(n.z, 0.0);
    }
    EXPECT_GT(boundaryEdgeCount(mesh), 0u);
}

TEST(MarchingTetrahedra, ResultDoesNotDependOnThreadCount)
{
    const TriangleMesh parallel = marchingTetrahedra(sphereOfRadius07, kUnitBox, 0.06);
    TriangleMesh serial;
    tbb::task_arena(1).execute(
        [&] { serial = marchingTetrahedra(sphereOfRadius07, kUnitBox, 0.06); });
    EXPECT_EQ(parallel.positions, serial.positions);
    EXPECT_EQ(parallel.triangles, serial.triangles);
}

TEST(MarchingTetrahedra, RejectsBadCellSizeAndBox)
{
    EXPECT_THROW(marchingTetrahedra(sphereOfRadius07, kUnitBox, 0.0), ValueError);
    EXPECT_THROW(marchingTetrahedra(sphereOfRadius07, kUnitBox,
                                    std::numeric_limits<double>::quiet_NaN()),
                 ValueError);
    EXPECT_THROW(marchingTetrahedra(sphereOfRadius07, kUnitBox, 1e-4), ValueError);  // 2e4^3 nodes
    EXPECT_THROW(marchingTetrahedra(sphereOfRadius07, {glm::dvec3(1.0), glm::dvec3(-1.0)}, 0.1),
                 ValueError);
}

}  // namespace
}  // namespace ivis::core
