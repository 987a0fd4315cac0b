/// @file triangle_bvh.h
/// @brief A BVH over a triangle mesh (Embree 3, robust mode): exact first ray hits and exact
///        closest points.
/// @warning Queries are thread-safe; build the BVH once and share it.
#pragma once

#include <ivis/core/closest_point.h>
#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <memory>

namespace ivis::core {

/// @brief The first triangle a ray hits.
struct RayHit {
    float t = 0.0f;           ///< ray parameter of the hit (distance for a unit direction)
    int triangle = -1;        ///< triangle index, -1 for a miss
    glm::vec3 barycentric{};  ///< weights of the triangle's vertices 0, 1, 2
    glm::vec3 normal{};       ///< unit geometric normal by the triangle's winding

    /// @brief True when something was hit.
    bool hit() const { return triangle >= 0; }
};

/// @brief Which hits count.
enum class FaceFilter {
    Any,       ///< the first hit
    BackOnly,  ///< the first hit on a triangle facing away from the ray (dot(normal, dir) > 0)
};

/// @brief A BVH over one triangle mesh (kept by reference: the mesh must outlive it).
class TriangleBvh {
public:
    /// @brief Builds the BVH; throws ValueError for an empty mesh.
    explicit TriangleBvh(const TriangleMesh& mesh);
    ~TriangleBvh();
    TriangleBvh(const TriangleBvh&) = delete;
    TriangleBvh& operator=(const TriangleBvh&) = delete;

    /// @brief First hit along origin + t dir, t in [tNear, tFar].
    RayHit intersect(const glm::vec3& origin, const glm::vec3& direction, float tNear = 0.0f,
                     float tFar = 1e30f, FaceFilter filter = FaceFilter::Any) const;

    /// @brief Exact closest point over all triangles to @a p (double precision), searching within
    ///        @a radius; ties go to the lowest triangle index.
    /// @param radius an upper bound on the distance (a guess speeds the search; infinity is fine)
    /// @param triangle output: the closest triangle, -1 when none lies within @a radius
    TrianglePoint closestPoint(const glm::dvec3& p, double radius, int& triangle) const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

}  // namespace ivis::core
