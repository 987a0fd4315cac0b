/// @file sampling_bound.h
/// @brief The most surface visibility (surface_voxels.h) that @a samples surface points can
///        measure: a picture of W x H pixels shows at most W H points, and a voxel the surface only
///        grazes holds so little of it that evenly spread points miss it. On the unit icosphere at
///        200^3, 400,000 even points see 95.1% of the surface voxels, a million 97.8%, four million
///        99.6% (docs/optimisation.md, "How much a picture can show").
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/optimize/surface_voxels.h>

#include <cstddef>

namespace ivis::optimize {

/// @brief Surface visibility of @a samples points spread evenly over the surface of @a mesh
///        (each triangle gets its share of the area, placed by a low-discrepancy sequence).
/// @throw ValueError when @a samples is 0 or the mesh has no area
double evenSamplingBound(const core::TriangleMesh& mesh, const SurfaceVoxels& voxels, std::size_t samples);

}  // namespace ivis::optimize
