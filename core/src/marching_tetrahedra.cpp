#include <ivis/core/marching_tetrahedra.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {
namespace {

// Cell corners and grid edges are coded by 3 bits (x = 1, y = 2, z = 4). Every tetrahedron of the
// Freudenthal split is a chain 0 -> a -> a|b -> 7 of corners, so each of its edges runs from a
// corner to a superset corner: the edge is (lower node, direction bits), seven per node.

/// Interpolation parameters stay this far from the nodes, so no two vertices coincide.
constexpr double kMinEdgeFraction = 1e-3;

/// The sampled grid plus, per node, which of its seven outgoing edges carry a vertex.
struct Lattice {
    glm::dvec3 origin{0.0};
    double cellSize = 1.0;
    std::array<std::int64_t, 3> nodes{};   ///< nodes per axis
    std::array<std::int64_t, 3> stride{};  ///< index step per axis
    std::vector<double> values;
    std::vector<std::uint8_t> edgeMask;     ///< bit d-1 set: edge in direction d has a vertex
    std::vector<std::uint32_t> firstVertex; ///< index of the node's first edge vertex

    bool inside(std::int64_t node) const { return values[node] < 0.0; }

    glm::dvec3 position(std::int64_t node) const
    {
        const std::int64_t i = node % nodes[0];
        const std::int64_t j = (node / nodes[0]) % nodes[1];
        const std::int64_t k = node / stride[2];
        return origin + cellSize * glm::dvec3(double(i), double(j), double(k));
    }

    std::int64_t offset(unsigned bits) const
    {
        return (bits & 1u ? stride[0] : 0) + (bits & 2u ? stride[1] : 0) +
               (bits & 4u ? stride[2] : 0);
    }

    /// Vertex on the edge from @a node along direction @a dir (1..7); the edge must cross.
    std::uint32_t edgeVertex(std::int64_t node, unsigned dir) const
    {
        const unsigned below = edgeMask[node] & ((1u << (dir - 1)) - 1u);
        return firstVertex[node] + std::uint32_t(std::bitset<8>(below).count());
    }
};

/// Sizes the grid over @a box and samples @a f at every node (slices in parallel).
Lattice sampleLattice(const ImplicitFunction& f, const Bounds3& box, double cellSize)
{
    Lattice lat;
    lat.origin = box.lo;
    lat.cellSize = cellSize;
    double total = 1.0;
    for (int a = 0; a < 3; ++a) {
        const double cells = std::max(1.0, std::ceil((box.hi[a] - box.lo[a]) / cellSize));
        total *= cells + 1.0;
        if (total > double(1u << 31))
            throw ValueError("marchingTetrahedra: grid too large (cell size " +
                             std::to_string(cellSize) + ")");
        lat.nodes[a] = std::int64_t(cells) + 1;
    }
    lat.stride = {1, lat.nodes[0], lat.nodes[0] * lat.nodes[1]};
    lat.values.resize(std::size_t(lat.stride[2] * lat.nodes[2]));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, lat.nodes[2]),
                      [&](const tbb::blocked_range<std::int64_t>& slices) {
                          for (std::int64_t k = slices.begin(); k != slices.end(); ++k)
                              for (std::int64_t n = k * lat.stride[2]; n < (k + 1) * lat.stride[2];
                                   ++n)
                                  lat.values[n] = f(lat.position(n));
                      });
    return lat;
}

/// Marks crossing edges and creates their vertices in node order (deterministic numbering).
std::vector<glm::vec3> placeVertices(Lattice& lat)
{
    const std::size_t count = lat.values.size();
    lat.edgeMask.assign(count, 0);
    lat.firstVertex.assign(count, 0);
    std::vector<glm::vec3> positions;
    for (std::int64_t k = 0; k < lat.nodes[2]; ++k)
        for (std::int64_t j = 0; j < lat.nodes[1]; ++j)
            for (std::int64_t i = 0; i < lat.nodes[0]; ++i) {
                const std::int64_t node = i + j * lat.stride[1] + k * lat.stride[2];
                lat.firstVertex[node] = std::uint32_t(positions.size());
                const glm::dvec3 p = lat.position(node);
                for (unsigned dir = 1; dir < 8; ++dir) {
                    const bool leavesGrid = ((dir & 1u) && i + 1 == lat.nodes[0]) ||
                                            ((dir & 2u) && j + 1 == lat.nodes[1]) ||
                                            ((dir & 4u) && k + 1 == lat.nodes[2]);
                    if (leavesGrid) continue;
                    const std::int64_t other = node + lat.offset(dir);
                    if (lat.inside(node) == lat.inside(other)) continue;
                    lat.edgeMask[node] |= std::uint8_t(1u << (dir - 1));
                    const double a = lat.values[node], b = lat.values[other];
                    const double t =
                        std::clamp(a / (a - b), kMinEdgeFraction, 1.0 - kMinEdgeFraction);
                    const glm::dvec3 q = lat.position(other);
                    positions.emplace_back(p + t * (q - p));
                }
            }
    return positions;
}

/// Appends the surface of one tetrahedron (corner codes along the chain) of the cell at @a base.
void polygoniseTet(const Lattice& lat, std::int64_t base, const std::array<unsigned, 4>& corner,
                   const std::vector<glm::vec3>& positions, TriangleMesh& mesh)
{
    std::array<unsigned, 4> in{}, out{};
    int nIn = 0, nOut = 0;
    for (unsigned c : corner) (lat.inside(base + lat.offset(c)) ? in[nIn++] : out[nOut++]) = c;
    if (nIn == 0 || nOut == 0) return;
    auto vertex = [&](unsigned c0, unsigned c1) {
        if (c0 > c1) std::swap(c0, c1);  // chain corners: the smaller code is the subset
        return lat.edgeVertex(base + lat.offset(c0), c1 ^ c0);
    };
    auto node = [&](unsigned c) { return lat.position(base + lat.offset(c)); };
    auto pos = [&](std::uint32_t v) { return glm::dvec3(positions[v]); };
    // Direction from the inside corners to the outside corners: the outward side.
    glm::dvec3 outward(0.0);
    for (int o = 0; o < nOut; ++o) outward += node(out[o]) / double(nOut);
    for (int i = 0; i < nIn; ++i) outward -= node(in[i]) / double(nIn);
    auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, const glm::dvec3& normal) {
        if (glm::dot(normal, outward) < 0.0) std::swap(b, c);
        mesh.triangles.push_back({a, b, c});
    };
    if (nIn == 2) {
        const std::array<std::uint32_t, 4> q{vertex(in[0], out[0]), vertex(in[0], out[1]),
                                             vertex(in[1], out[1]), vertex(in[1], out[0])};
        const glm::dvec3 normal = glm::cross(pos(q[2]) - pos(q[0]), pos(q[3]) - pos(q[1]));
        emit(q[0], q[1], q[2], normal);
        emit(q[0], q[2], q[3], normal);
        return;
    }
    const unsigned apex = nIn == 1 ? in[0] : out[0];
    const std::array<unsigned, 4>& rest = nIn == 1 ? out : in;
    const std::uint32_t a = vertex(apex, rest[0]), b = vertex(apex, rest[1]),
                        c = vertex(apex, rest[2]);
    emit(a, b, c, glm::cross(pos(b) - pos(a), pos(c) - pos(a)));
}

}  // namespace

TriangleMesh marchingTetrahedra(const ImplicitFunction& f, const Bounds3& box, double cellSize)
{
    if (!(cellSize > 0.0) || !std::isfinite(cellSize))
        throw ValueError("marchingTetrahedra: cell size must be positive, got " +
                         std::to_string(cellSize));
    for (int a = 0; a < 3; ++a)
        if (!(box.hi[a] >= box.lo[a]) || !std::isfinite(box.hi[a] - box.lo[a]))
            throw ValueError("marchingTetrahedra: empty or non-finite box");
    Lattice lat = sampleLattice(f, box, cellSize);
    TriangleMesh mesh;
    mesh.positions = placeVertices(lat);
    static const std::array<std::array<unsigned, 3>, 6> kAxisOrders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    for (std::int64_t k = 0; k + 1 < lat.nodes[2]; ++k)
        for (std::int64_t j = 0; j + 1 < lat.nodes[1]; ++j)
            for (std::int64_t i = 0; i + 1 < lat.nodes[0]; ++i) {
                const std::int64_t base = i + j * lat.stride[1] + k * lat.stride[2];
                int insideCorners = 0;
                for (unsigned c = 0; c < 8; ++c) insideCorners += lat.inside(base + lat.offset(c));
                if (insideCorners == 0 || insideCorners == 8) continue;
                for (const auto& order : kAxisOrders) {
                    const unsigned c1 = 1u << order[0], c2 = c1 | (1u << order[1]);
                    polygoniseTet(lat, base, {0u, c1, c2, 7u}, mesh.positions, mesh);
                }
            }
    mesh.dataTriangleCount = mesh.triangles.size();
    return mesh;
}

}  // namespace ivis::core
