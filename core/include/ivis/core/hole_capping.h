/// @file hole_capping.h
/// @brief Closes the boundary loops of an open mesh with fan caps tagged as non-data.
#pragma once

#include <ivis/core/surface_field.h>

#include <cstddef>

namespace ivis::core {

/// @brief Appends, for each boundary loop, a centroid vertex and a triangle fan closing it.
///        Cap triangles come after dataTriangleCount, so they are never coloured as data; the new
///        vertices get a NaN value when a per-vertex scalar is shown. Each cap triangle runs its
///        boundary edge opposite to the triangle beside it, so orientation carries over the seam.
/// @return number of loops capped (0 for a closed mesh)
std::size_t capHoles(SurfaceField& field);

}  // namespace ivis::core
