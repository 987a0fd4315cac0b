#include <ivis/core/clustered_vertices.h>

#include <ivis/core/errors.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <utility>

namespace ivis::core {
namespace {

/// @a v's low 10 bits spread to every third bit.
std::uint32_t spreadBits(std::uint32_t v)
{
    v &= 0x3ffu;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

}  // namespace

ClusteredVertices::ClusteredVertices(const std::vector<glm::vec3>& positions, std::size_t perCluster)
{
    if (perCluster == 0) throw ValueError("a cluster of vertices must hold at least one");
    glm::vec3 lo(0.0f), hi(0.0f);
    if (!positions.empty()) lo = hi = positions.front();
    for (const glm::vec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 cells = glm::vec3(1023.0f) / glm::max(hi - lo, glm::vec3(1e-30f));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::uvec3 cell(glm::clamp((positions[i] - lo) * cells, glm::vec3(0.0f), glm::vec3(1023.0f)));
        order[i] = {spreadBits(cell.x) | (spreadBits(cell.y) << 1) | (spreadBits(cell.z) << 2), std::uint32_t(i)};
    }
    tbb::parallel_sort(order.begin(), order.end());
    mPositions.reserve(positions.size());
    for (const auto& entry : order) mPositions.push_back(positions[entry.second]);
    // Octree cells in Morton order, split while they hold more than perCluster vertices (a run
    // of the order cut at fixed lengths would straddle far-apart cells).
    const auto addCluster = [this](std::size_t begin, std::size_t end) {
        Cluster cluster;
        cluster.begin = begin;
        cluster.end = end;
        glm::dvec3 boxLo(mPositions[begin]), boxHi(mPositions[begin]);
        for (std::size_t i = begin; i < end; ++i) {
            boxLo = glm::min(boxLo, glm::dvec3(mPositions[i]));
            boxHi = glm::max(boxHi, glm::dvec3(mPositions[i]));
        }
        cluster.centre = 0.5 * (boxLo + boxHi);
        for (std::size_t i = begin; i < end; ++i)
            cluster.radius = std::max(cluster.radius, glm::length(glm::dvec3(mPositions[i]) - cluster.centre));
        cluster.radius = cluster.radius * (1.0 + 1e-9) + 1e-12;  // holds its vertices whatever the rounding
        mClusters.push_back(cluster);
    };
    const auto split = [&](auto&& self, std::size_t begin, std::size_t end, int shift) -> void {
        if (end - begin <= perCluster || shift < 0) {
            for (std::size_t b = begin; b < end; b += perCluster) addCluster(b, std::min(end, b + perCluster));
            return;
        }
        while (begin < end) {  // the children: runs sharing the code's bits above shift
            const std::uint32_t cell = order[begin].first >> shift;
            const auto first = order.begin() + std::ptrdiff_t(begin), last = order.begin() + std::ptrdiff_t(end);
            const auto childEnd = std::upper_bound(first, last, cell, [shift](std::uint32_t c, const auto& entry) {
                return c < (entry.first >> shift);
            });
            const std::size_t next = std::size_t(childEnd - order.begin());
            self(self, begin, next, shift - 3);
            begin = next;
        }
    };
    split(split, 0, order.size(), 27);
}

}  // namespace ivis::core
