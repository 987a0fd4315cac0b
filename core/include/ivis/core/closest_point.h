/// @file closest_point.h
/// @brief Exact closest point on a triangle, with barycentric coordinates.
/// @note Works for degenerate (zero-area) triangles too: the result is the closest point on an edge.
#pragma once

#include <glm/vec3.hpp>

namespace ivis::core {

/// @brief Closest point on a triangle to a query point.
struct TrianglePoint {
    glm::dvec3 point{0.0};        ///< closest point, same space as the input
    glm::dvec3 barycentric{0.0};  ///< weights of (a, b, c), each in [0,1], summing to 1
    double distanceSquared = 0.0;
};

/// @brief Exact closest point to @a p on triangle (a, b, c) (Ericson, Real-Time Collision
///        Detection, 5.1.5: Voronoi regions of vertices, edges and face).
TrianglePoint closestPointOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                     const glm::dvec3& c);

/// @brief closestPointOnTriangle of @a p on each of @a count triangles, the corners of triangle i
///        at corners[3 i], corners[3 i + 1], corners[3 i + 2], into out[i]: the same bits, four
///        triangles at a time in vector registers (AVX2 where the CPU has it) without branches.
void closestPointsOnTriangles(const glm::dvec3& p, const glm::dvec3* corners, int count, TrianglePoint* out);

}  // namespace ivis::core
