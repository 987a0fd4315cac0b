/// @file similarity.h
/// @brief The normalising transform between a mesh's own units and the normalised units every
///        picture, camera and layer uses (the mesh's bounding box centred at 0, its longest side
///        spanning [-1, 1]), and how outputs record it.
#pragma once

#include <glm/vec3.hpp>

#include <nlohmann/json.hpp>

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


/// @brief The transform as outputs record it: {"center": [x, y, z], "scale": s, "mesh_from_normalised":
///        "p / scale + center"} (center and lengths in the mesh's own units).
nlohmann::json meshUnitsJson(const Similarity& similarity);

}  // namespace ivis::core
