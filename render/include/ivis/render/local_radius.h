/// @file local_radius.h
/// @brief How thick a surface is where: half the distance through the object from each vertex
///        to the other side (a one-ray shape diameter), which sizes the rings of inversevis-wrap.
#pragma once

#include <ivis/core/triangle_bvh.h>
#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <vector>

namespace ivis::render {

/// @brief Half the mesh's thickness at each vertex: half the distance along the inward normal
///        (-@a normals) to the first triangle seen from inside, @a cap where that ray leaves through
///        an opening or the thickness exceeds it; then averaged 32 times over each vertex's
///        triangles, so that it changes little from vertex to vertex where sharp edges make one
///        ray's thickness jump.
std::vector<float> vertexLocalRadii(const core::TriangleMesh& mesh, const core::TriangleBvh& bvh,
                                    const std::vector<glm::vec3>& normals, float cap);

}  // namespace ivis::render
