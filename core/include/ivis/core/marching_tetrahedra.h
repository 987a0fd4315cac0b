/// @file marching_tetrahedra.h
/// @brief Polygonises the zero level set of an implicit function on a regular grid.
/// @note The surface must lie strictly inside the box; where it leaves the box the mesh is open.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <functional>

namespace ivis::core {

/// @brief Scalar function of a point; negative inside the shape, positive outside.
using ImplicitFunction = std::function<double(const glm::dvec3&)>;

/// @brief Extracts the surface f = 0 as an indexed mesh with shared vertices, using the
///        Freudenthal split of each grid cell into six tetrahedra (crack-free, no ambiguous cases).
/// @param f implicit function, negative inside; evaluated once per grid node
/// @param box region sampled, in the same space as @a f; nodes start at box.lo
/// @param cellSize grid spacing (same units as @a box); the grid covers at least the whole box
/// @return mesh whose vertices lie on tetrahedron edges (linear interpolation of f, kept at least
///         1e-3 of an edge away from grid nodes, so vertices never coincide), triangles oriented
///         outward (away from f < 0), dataTriangleCount = number of triangles
/// @throw ValueError for a non-positive or non-finite cell size, an empty box, or more than
///        2^31 grid nodes
/// @warning @a f is called concurrently from several threads; the result does not depend on the
///          number of threads.
TriangleMesh marchingTetrahedra(const ImplicitFunction& f, const Bounds3& box, double cellSize);

}  // namespace ivis::core
