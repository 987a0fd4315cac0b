/// @file surface_field.h
/// @brief A triangle mesh with one per-vertex scalar field and its normalising transform.
/// @note After normalize(), positions lie in [-1,1]^3; meshFromNormalized maps them back.
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace ivis::core {

/// @brief Uniform scale + translation: normalised = (file - center) * scale.
struct Similarity {
    glm::dvec3 center{0.0};
    double scale = 1.0;

    /// @brief Maps a point from the mesh's own units to normalised units.
    glm::dvec3 normalizedFromMesh(const glm::dvec3& p) const { return (p - center) * scale; }
    /// @brief Maps a point from normalised units back to the mesh's own units.
    glm::dvec3 meshFromNormalized(const glm::dvec3& p) const { return p / scale + center; }
    /// @brief Converts a length in normalised units to the mesh's own units.
    double meshLength(double normalizedLength) const { return normalizedLength / scale; }
};

/// @brief Mesh + optional per-vertex scalar (values.size() is 0 or positions.size(); NaN allowed).
struct SurfaceField {
    TriangleMesh mesh;
    std::vector<float> values;
    std::string name;          ///< scalar name ("" when there is no scalar)
    std::string sourcePath;    ///< file it came from, or "generated:<scene>"
    Similarity normalization;  ///< identity until normalize() is called

    /// @brief True when a scalar is attached.
    bool hasScalar() const { return !values.empty(); }
};

/// @brief Scales and centres the mesh uniformly so its bounding box fits [-1,1]^3 (longest side
///        spans exactly [-1,1]); records the transform in field.normalization.
/// @throw ValueError if the mesh has zero extent.
void normalize(SurfaceField& field);

/// @brief Finite (min, max) of the values, ignoring NaN; {0,0} when there is none.
std::pair<float, float> finiteRange(const std::vector<float>& values);

}  // namespace ivis::core
