#include <ivis/core/triangle_mesh.h>

#include <ivis/core/errors.h>

#include <glm/common.hpp>

#include <algorithm>
#include <numeric>
#include <utility>

namespace ivis::core {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;  // (from, to) as the triangle traverses it

/// Undirected key of an edge: (smaller index, larger index).
Edge undirected(Edge e) { return {std::min(e.first, e.second), std::max(e.first, e.second)}; }

/// Edges used by exactly one triangle, each in the direction its triangle traverses it, sorted by
/// undirected key. Edges of a repeated vertex (a, a) are not edges and are skipped. The edges are
/// bucketed by their smaller vertex (a counting sort) and each bucket, a handful, sorted by the
/// larger: linear in the edges, where one sort of them all took most of a 1.6M-triangle load.
std::vector<Edge> boundaryEdges(const TriangleMesh& mesh)
{
    const std::size_t vertexCount = mesh.positions.size();
    std::vector<std::uint32_t> start(vertexCount + 1, 0);  // start[v + 1]: edges whose smaller vertex is v
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Edge e = undirected({t[k], t[(k + 1) % 3]});
            IVIS_CHECK(e.second < vertexCount);
            if (e.first != e.second) ++start[e.first + 1];
        }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<Edge> edges(start[vertexCount]);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Edge e{t[k], t[(k + 1) % 3]};
            if (e.first != e.second) edges[fill[std::min(e.first, e.second)]++] = e;
        }
    const auto byLarger = [](const Edge& a, const Edge& b) {
        return std::max(a.first, a.second) < std::max(b.first, b.second);
    };
    for (std::size_t v = 0; v < vertexCount; ++v)
        std::sort(edges.begin() + std::ptrdiff_t(start[v]), edges.begin() + std::ptrdiff_t(start[v + 1]), byLarger);

    std::vector<Edge> boundary;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && undirected(edges[j]) == undirected(edges[i])) ++j;
        if (j - i == 1) boundary.push_back(edges[i]);
        i = j;
    }
    return boundary;
}

/// Union-find root with path halving.
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v)
{
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

}  // namespace

Bounds3 bounds(const TriangleMesh& mesh)
{
    if (mesh.positions.empty()) throw ValueError("bounds: the mesh has no vertices");
    Bounds3 b{glm::dvec3(mesh.positions.front()), glm::dvec3(mesh.positions.front())};
    for (const glm::vec3& p : mesh.positions) {
        b.lo = glm::min(b.lo, glm::dvec3(p));
        b.hi = glm::max(b.hi, glm::dvec3(p));
    }
    return b;
}

std::size_t boundaryEdgeCount(const TriangleMesh& mesh) { return boundaryEdges(mesh).size(); }

std::size_t componentCount(const TriangleMesh& mesh)
{
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<bool> used(mesh.positions.size(), false);
    for (const auto& t : mesh.triangles) {
        for (std::uint32_t v : t) IVIS_CHECK(v < parent.size());
        for (int k = 0; k < 3; ++k) used[t[k]] = true;
        parent[findRoot(parent, t[1])] = findRoot(parent, t[0]);
        parent[findRoot(parent, t[2])] = findRoot(parent, t[0]);
    }
    std::size_t count = 0;
    for (std::uint32_t v = 0; v < parent.size(); ++v) {
        if (used[v] && findRoot(parent, v) == v) ++count;
    }
    return count;
}

std::vector<std::vector<std::uint32_t>> boundaryLoops(const TriangleMesh& mesh)
{
    const std::vector<Edge> edges = boundaryEdges(mesh);

    // Incident boundary edges per vertex (CSR layout).
    std::vector<std::uint32_t> start(mesh.positions.size() + 1, 0);
    for (const Edge& e : edges) {
        IVIS_CHECK(e.first < mesh.positions.size() && e.second < mesh.positions.size());
        ++start[e.first + 1];
        ++start[e.second + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> incident(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
        incident[fill[edges[i].first]++] = i;
        incident[fill[edges[i].second]++] = i;
    }

    // Walk along unvisited boundary edges; at a vertex with several candidates (non-manifold),
    // prefer the edge that leaves it in its triangle's direction. Every step consumes one edge,
    // so the walk ends, and every edge lands in exactly one loop.
    std::vector<bool> visited(edges.size(), false);
    const auto nextEdge = [&](std::uint32_t v) -> std::int64_t {
        std::int64_t fallback = -1;
        for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
            const std::uint32_t e = incident[k];
            if (visited[e]) continue;
            if (edges[e].first == v) return e;
            if (fallback < 0) fallback = e;
        }
        return fallback;
    };

    std::vector<std::vector<std::uint32_t>> loops;
    for (std::uint32_t first = 0; first < edges.size(); ++first) {
        if (visited[first]) continue;
        const std::uint32_t origin = edges[first].first;
        std::vector<std::uint32_t> loop{origin};
        visited[first] = true;
        std::uint32_t v = edges[first].second;
        while (v != origin) {
            loop.push_back(v);
            const std::int64_t e = nextEdge(v);
            if (e < 0) break;  // open chain (possible only at non-manifold vertices)
            visited[e] = true;
            v = edges[e].first == v ? edges[e].second : edges[e].first;
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace ivis::core
