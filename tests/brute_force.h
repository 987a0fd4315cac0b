/// @file brute_force.h
/// @brief Exhaustive reference answers for tests: closest point over all triangles, inside test.
#pragma once

#include <ivis/core/closest_point.h>
#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace ivis::test {

/// @brief Exhaustive closest-point search (every triangle is considered; bounding spheres only
///        skip triangles that provably cannot be closer).
class BruteForceClosest {
public:
    explicit BruteForceClosest(const core::TriangleMesh& mesh);
    /// @brief Closest point over all triangles and the index of a triangle attaining it.
    core::TrianglePoint closest(const glm::dvec3& p, std::int32_t* triangle = nullptr) const;
    /// @brief Generalised winding number at p (about 1 inside a closed outward mesh, 0 outside).
    double windingNumber(const glm::dvec3& p) const;
    /// @brief Gradient of the signed distance of a closed mesh at p: the unit vector from the
    ///        closest point, negated inside.
    glm::dvec3 distanceGradient(const glm::dvec3& p) const;

private:
    const core::TriangleMesh& mMesh;
    std::vector<glm::dvec3> mCentres;
    std::vector<double> mRadii;
};

}  // namespace ivis::test
