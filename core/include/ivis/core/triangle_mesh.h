/// @file triangle_mesh.h
/// @brief An indexed triangle mesh and its topological facts (boundary edges, components).
/// @note Triangles at index >= dataTriangleCount are hole caps: geometry only, never coloured as data.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ivis::core {

/// @brief Axis-aligned bounding box.
struct Bounds3 {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{0.0};
};

/// @brief Indexed triangle mesh; positions in the space the owner states (file or normalised).
struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    /// Triangles [0, dataTriangleCount) come from the input; the rest are caps added by capHoles.
    std::size_t dataTriangleCount = 0;

    /// @brief True when triangle @a t is a hole cap (not input data).
    bool isCap(std::size_t t) const { return t >= dataTriangleCount; }
};

/// @brief Bounding box of all positions; throws ValueError for an empty mesh.
Bounds3 bounds(const TriangleMesh& mesh);

/// @brief Number of undirected edges used by exactly one triangle (0 for a closed mesh).
std::size_t boundaryEdgeCount(const TriangleMesh& mesh);

/// @brief Number of connected components through shared vertices (isolated vertices ignored).
std::size_t componentCount(const TriangleMesh& mesh);

/// @brief Boundary loops as vertex index cycles (each loop listed once, in edge order).
/// @note Loops run the way the triangles traverse their boundary edges where orientation allows.
///       Every boundary edge lies in exactly one loop; at a non-manifold boundary vertex (more
///       than two boundary edges) a walk may end as an open chain, whose last and first vertices
///       are then not joined by an edge.
std::vector<std::vector<std::uint32_t>> boundaryLoops(const TriangleMesh& mesh);

}  // namespace ivis::core
