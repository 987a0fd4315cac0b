/// @file pseudo_normals.h
/// @brief Angle-weighted pseudo-normals (Baerentzen & Aanaes 2005): the sign of
///        dot(p - closest point, pseudo-normal of the closest feature) is the exact inside/outside
///        sign for a closed, manifold, consistently oriented mesh.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ivis::core {

/// @brief Pseudo-normals of faces, edges and vertices, oriented outward.
class PseudoNormals {
public:
    /// @brief Computes the normals; usable() is false unless every edge has exactly two triangles
    ///        traversing it in opposite directions. Orientation follows the sign of the enclosed volume.
    explicit PseudoNormals(const TriangleMesh& mesh);

    /// @brief True for a closed, manifold, consistently oriented mesh (signs are then exact).
    bool usable() const { return mUsable; }

    /// @brief Outward pseudo-normal of the feature holding the closest point with barycentric
    ///        weights @a barycentric on @a triangle: the face, an edge (one weight zero) or a vertex.
    glm::dvec3 at(int triangle, const glm::dvec3& barycentric) const;

private:
    const TriangleMesh& mMesh;
    bool mUsable = false;
    std::vector<glm::dvec3> mFace;
    std::vector<glm::dvec3> mVertex;
    std::unordered_map<std::uint64_t, glm::dvec3> mEdge;
};

}  // namespace ivis::core
