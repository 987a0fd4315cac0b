/// @file surface_point.h
/// @brief A point on the mesh (triangle + barycentrics) and the scalar interpolated there.
#pragma once

#include <ivis/core/surface_field.h>

#include <glm/vec3.hpp>

#include <vector>

namespace ivis::render {

/// @brief A point on a triangle of the mesh.
struct SurfacePoint {
    int triangle = -1;        ///< -1: no point
    glm::vec3 barycentric{};  ///< weights of the triangle's vertices 0, 1, 2
    glm::vec3 position{};     ///< normalised coordinates

    /// @brief True when the point exists.
    bool valid() const { return triangle >= 0; }
};

/// @brief Exact closest point to @a p on triangle @a triangle of @a mesh.
SurfacePoint projectOntoTriangle(const core::TriangleMesh& mesh, int triangle, const glm::vec3& p);

/// @brief Surface point from a triangle and barycentric weights.
SurfacePoint pointOnTriangle(const core::TriangleMesh& mesh, int triangle, const glm::vec3& barycentric);

/// @brief The shown scalar at @a point (core::scalarAt: a cell value, or the linear blend of the
///        vertex values); NaN for no point, a cap triangle, a field without scalar or a NaN value.
float scalarAt(const core::SurfaceField& field, const SurfacePoint& point);

/// @brief Unit geometric normal of the point's triangle (by its winding).
glm::vec3 triangleNormal(const core::TriangleMesh& mesh, int triangle);

/// @brief Area-weighted unit vertex normals (by the triangles' winding).
std::vector<glm::vec3> vertexNormals(const core::TriangleMesh& mesh);

/// @brief Smooth shading normal at @a point: barycentric blend of @a normals (one per vertex),
///        falling back to the triangle normal where the blend vanishes.
glm::vec3 shadingNormal(const core::TriangleMesh& mesh, const std::vector<glm::vec3>& normals,
                        const SurfacePoint& point);

}  // namespace ivis::render
