/// @file voxel_pieces.h
/// @brief A triangle cut exactly into its pieces inside the voxels of a lattice (cell space:
///        voxel (i, j, k) is [i, i + 1) x [j, j + 1) x [k, k + 1)), for the area the surface
///        holds inside each voxel (surface_voxels.h).
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <functional>

namespace ivis::optimize {

/// @brief A convex polygon of at most 12 corners (a triangle cut by six planes has at most 9).
struct ConvexPiece {
    std::array<glm::dvec3, 12> corners{};
    int size = 0;
};

/// @brief Area of a convex polygon, in the units of its corners.
double pieceArea(const ConvexPiece& piece);

/// @brief Cuts the triangle @a a, @a b, @a c (cell coordinates) along the integer planes of every
///        axis and calls @a visit with each piece's voxel and the piece (pieces of zero area included).
void cutIntoVoxels(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                   const std::function<void(const glm::ivec3& voxel, const ConvexPiece& piece)>& visit);

}  // namespace ivis::optimize
