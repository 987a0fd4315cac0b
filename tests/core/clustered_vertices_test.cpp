// ClusteredVertices: a permutation of the vertices, cut into runs no longer than asked, each inside
// its ball, and the runs spatially compact (octree cells in Morton order).
#include <ivis/core/clustered_vertices.h>
#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>
#include <vector>

namespace ivis::core {
namespace {

bool before(const glm::vec3& a, const glm::vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); }

TEST(ClusteredVertices, RunsCoverEveryVertexOnceInsideTheirBalls)
{
    const std::vector<glm::vec3> positions = makeVesselTree().mesh.positions;
    for (std::size_t perCluster : {std::size_t(1), std::size_t(7), kVerticesPerCluster, positions.size() + 5}) {
        const ClusteredVertices vertices(positions, perCluster);
        std::vector<glm::vec3> sorted = vertices.positions(), expected = positions;
        std::sort(sorted.begin(), sorted.end(), before);
        std::sort(expected.begin(), expected.end(), before);
        EXPECT_EQ(sorted, expected) << perCluster;
        std::size_t next = 0;
        for (const ClusteredVertices::Cluster& cluster : vertices.clusters()) {
            EXPECT_EQ(cluster.begin, next);
            EXPECT_GT(cluster.end, cluster.begin);
            EXPECT_LE(cluster.end - cluster.begin, perCluster);
            for (std::size_t i = cluster.begin; i < cluster.end; ++i)
                EXPECT_LE(glm::length(glm::dvec3(vertices.positions()[i]) - cluster.centre), cluster.radius);
            next = cluster.end;
        }
        EXPECT_EQ(next, positions.size());
    }
}

// The runs are small against the mesh: in a random order each would be nearly as wide as the whole
// tree, and runs of the Morton order cut at fixed lengths averaged 7% of its diagonal (octree cells: 2%).
TEST(ClusteredVertices, RunsAreCompact)
{
    const std::vector<glm::vec3> positions = makeVesselTree().mesh.positions;
    glm::vec3 lo = positions.front(), hi = lo;
    for (const glm::vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const ClusteredVertices vertices(positions);
    double meanRadius = 0.0;
    for (const ClusteredVertices::Cluster& cluster : vertices.clusters()) meanRadius += cluster.radius;
    meanRadius /= double(vertices.clusters().size());
    EXPECT_LT(meanRadius, 0.03 * glm::length(hi - lo));
}

TEST(ClusteredVertices, EmptyListsAndEmptyClusters)
{
    EXPECT_TRUE(ClusteredVertices({}).clusters().empty());
    EXPECT_THROW(ClusteredVertices({glm::vec3(0.0f)}, 0), ValueError);
    const ClusteredVertices one({glm::vec3(1.0f, 2.0f, 3.0f)});
    ASSERT_EQ(one.clusters().size(), 1u);
    EXPECT_EQ(one.clusters()[0].centre, glm::dvec3(1.0, 2.0, 3.0));
}

}  // namespace
}  // namespace ivis::core
