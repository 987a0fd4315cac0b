/// @file hot_spots.h
/// @brief A generated scalar for the reveal measure (docs/measures.md, 3): Gaussian hot
///        spots at the ends of the mesh's thinnest principal axis, so that no straight view shows
///        both (the paper's Fig. 7 set-up).
#pragma once

#include <ivis/core/triangle_mesh.h>

#include <glm/vec3.hpp>

#include <vector>

namespace ivis::core {

/// @brief Where the hot spots sit and how wide they are.
struct HotSpots {
    std::vector<glm::vec3> centres;  ///< surface vertices, one per spot
    float sigma = 0.0f;              ///< Gaussian width (units of the mesh's positions)
};

/// @brief The most hot spots placeHotSpots places (two along each principal axis).
inline constexpr int kMaxHotSpots = 6;

/// @brief Places @a count spots: the first two at the vertices furthest along -a and +a for the
///        thinnest principal axis a (of the vertices' covariance), the next two along the middle
///        axis, the last two along the longest; sigma is 6% of the bounding-box diagonal.
/// @throw ValueError unless 1 <= count <= kMaxHotSpots, or for a mesh without vertices
HotSpots placeHotSpots(const TriangleMesh& mesh, int count);

/// @brief Per-vertex value in [0, 1]: the largest exp(-d^2 / (2 sigma^2)) over the spots, d the
///        straight-line distance from the spot's centre.
std::vector<float> hotSpotValues(const TriangleMesh& mesh, const HotSpots& spots);

}  // namespace ivis::core
