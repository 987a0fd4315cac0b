/// @file box_lattice.h
/// @brief The voxel lattice of a resolution over the box [-2.5, 2.5]^3: voxel centre i sits at
///        -2.5 + (i + 0.5) * 5 / resolution on every axis.
/// @note Index space puts voxel centres at integers (OpenVDB's convention); cell space puts voxel i
///       on [i, i + 1). Voxels are isotropic, so one axis formula serves all three axes.
#pragma once

#include <openvdb/openvdb.h>

namespace ivis::vdb {

/// @brief Half the edge of the cube [-kBoxHalfExtent, kBoxHalfExtent]^3 every lattice spans.
inline constexpr double kBoxHalfExtent = 2.5;

/// @brief A lattice of @a resolution voxels across the box, per axis in world (normalised) units.
struct BoxLattice {
    int resolution = 0;  ///< voxels across the box (> 0)

    /// @brief Voxel edge in world units: 5 / resolution.
    double voxelSize() const { return 2.0 * kBoxHalfExtent / resolution; }
    /// @brief World coordinate of index coordinate @a i (a voxel centre when @a i is an integer).
    double worldFromIndex(double i) const { return -kBoxHalfExtent + (i + 0.5) * voxelSize(); }
    /// @brief World position of voxel @a ijk as OpenVDB's scale-then-translate map computes it:
    ///        ijk * voxelSize + worldFromIndex(0) per axis.
    /// @note May differ in the last bit from worldFromIndex(double), which rounds differently.
    openvdb::Vec3d worldFromIndex(const openvdb::Coord& ijk) const
    {
        const double origin = worldFromIndex(0.0), size = voxelSize();
        return {origin + ijk.x() * size, origin + ijk.y() * size, origin + ijk.z() * size};
    }
    /// @brief Cell coordinate of world coordinate @a x: floor() of it is the voxel containing @a x.
    double cellFromWorld(double x) const { return (x + kBoxHalfExtent) / voxelSize(); }
    /// @brief Index coordinate of world coordinate @a x (inverse of worldFromIndex up to rounding).
    double indexFromWorld(double x) const { return cellFromWorld(x) - 0.5; }
    /// @brief OpenVDB index-to-world transform of the lattice (uniform scale, then translation).
    /// @note Its indexToWorld computes worldFromIndex(Coord); a grid that OpenVDB built with it
    ///       may carry a scale a few ulps off (see box_lattice_test), so index from the lattice.
    openvdb::math::Transform::Ptr transform() const;
};

}  // namespace ivis::vdb
