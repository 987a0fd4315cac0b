/// @file generated_field.h
/// @brief What the generated scenes share: a finished mesh wrapped with its scalar, and the
///        Gaussian bump their hot spots are made of (core/src only).
#pragma once

#include <ivis/core/surface_field.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <utility>

namespace ivis::core::generated {

constexpr double kPi = 3.14159265358979323846;

/// @brief A scalar given at a point of space.
using ScalarFunction = std::function<double(const glm::dvec3&)>;

/// @brief exp(-|p - center|^2 / (2 width^2)).
inline double gaussian(const glm::dvec3& p, const glm::dvec3& center, double width)
{
    const glm::dvec3 d = p - center;
    return std::exp(-glm::dot(d, d) / (2.0 * width * width));
}

/// @brief Wraps a finished mesh (already in [-1,1]^3) with its scalar evaluated at every vertex.
inline SurfaceField makeField(TriangleMesh mesh, const std::string& scene, const std::string& scalarName,
                       const ScalarFunction& scalar)
{
    SurfaceField field;
    mesh.dataTriangleCount = mesh.triangles.size();
    field.values.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) field.values.push_back(float(scalar(glm::dvec3(p))));
    field.mesh = std::move(mesh);
    field.name = scalarName;
    field.sourcePath = "generated:" + scene;
    return field;
}

}  // namespace ivis::core::generated
