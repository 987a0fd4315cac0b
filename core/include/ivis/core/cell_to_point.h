/// @file cell_to_point.h
/// @brief Values per triangle averaged onto the vertices, weighted by triangle area (the smooth
///        picture of a cell array).
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <vector>

namespace ivis::core {

/// @brief At each vertex, the area-weighted mean of the finite values of the data triangles
///        around it; NaN where there is none.
/// @param perTriangle one value per data triangle (size mesh.dataTriangleCount)
std::vector<float> cellToPoint(const TriangleMesh& mesh, const std::vector<float>& perTriangle);

}  // namespace ivis::core
