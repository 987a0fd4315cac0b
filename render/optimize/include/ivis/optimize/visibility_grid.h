/// @file visibility_grid.h
/// @brief The paper's visibility measure read literally ("paper_literal", docs/measures.md, 1): voxels of a grid over the box whose centre lies closer to the surface than
///        one voxel are "marked"; a marked voxel is "visited" when a ray lands in it; visibility =
///        visited / marked. About a third of the marked voxels contain no surface, so its ceiling
///        is 65-73%: reported beside surface visibility (surface_voxels.h), never optimised.
/// @note Sparse: only the marked voxels are stored (sorted keys), so any resolution works.
#pragma once

#include <ivis/core/triangle_bvh.h>
#include <ivis/core/triangle_mesh.h>
#include <ivis/optimize/surface_voxels.h>
#include <ivis/vdb/box_lattice.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace ivis::optimize {

/// @brief Marked voxels of a resolution^3 grid over [-2.5, 2.5]^3.
class VisibilityGrid {
public:
    /// @brief Marks every voxel whose centre is within one voxel of the mesh (exact distance).
    /// @param resolution voxels across the box (paper: 200)
    VisibilityGrid(const core::TriangleMesh& mesh, const core::TriangleBvh& bvh, int resolution = 200);

    /// @brief Key of the voxel containing @a p, or kNoVoxel outside the box.
    std::uint64_t keyOf(const glm::vec3& p) const { return voxelKey(mLattice, p); }
    /// @brief Number of marked voxels among @a keys (sorted and deduplicated in place).
    std::size_t countMarked(std::vector<std::uint64_t>& keys) const;
    /// @brief visited marked voxels / marked voxels for the voxels of @a keys.
    double fractionVisited(std::vector<std::uint64_t>& keys) const;
    /// @brief Number of marked voxels.
    std::size_t markedCount() const { return mMarked.size(); }
    /// @brief Voxels across the box.
    int resolution() const { return mLattice.resolution; }
    /// @brief Voxel edge (normalised units).
    double voxelSize() const { return mLattice.voxelSize(); }

private:
    vdb::BoxLattice mLattice;
    std::vector<std::uint64_t> mMarked;  ///< sorted keys
};

}  // namespace ivis::optimize
