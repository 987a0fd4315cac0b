/// @file clustered_vertices.h
/// @brief A mesh's vertices in small spatial clusters, each inside a bounding ball, so that a search
///        for the vertex that reaches farthest by some measure can skip whole clusters.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace ivis::core {

/// @brief Vertices per cluster by default: a few hundred bounds stand for 100k vertices.
inline constexpr std::size_t kVerticesPerCluster = 128;

/// @brief A copy of a vertex list in Morton order (1024 cells per axis of its bounding box), cut into
///        runs of at most a given size along the cells of its octree (a run never straddles two
///        cells of a level where the cell holds more), each with a ball that holds its vertices.
class ClusteredVertices {
public:
    /// @brief One run of vertices and its bounding ball.
    struct Cluster {
        glm::dvec3 centre{0.0};  ///< the centre of the run's bounding box
        double radius = 0.0;     ///< every vertex of the run lies within this distance of centre (rounded up)
        std::size_t begin = 0;   ///< the run's first vertex in positions()
        std::size_t end = 0;     ///< one past its last
    };

    /// @brief Sorts @a positions into clusters of at most @a perCluster vertices (>= 1).
    explicit ClusteredVertices(const std::vector<glm::vec3>& positions, std::size_t perCluster = kVerticesPerCluster);
    /// @brief The vertices, cluster by cluster.
    const std::vector<glm::vec3>& positions() const { return mPositions; }
    /// @brief The clusters, covering positions() in order.
    const std::vector<Cluster>& clusters() const { return mClusters; }

private:
    std::vector<glm::vec3> mPositions;
    std::vector<Cluster> mClusters;
};

}  // namespace ivis::core
