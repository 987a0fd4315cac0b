/// @file surface_voxels.h
/// @brief Surface visibility, the primary measure (docs/measures.md, 1): on a grid of
///        resolution^3 voxels over [-2.5, 2.5]^3 (200 by default), a voxel is a surface voxel when
///        the surface passes through it, and it is seen when the surface point P of some pixel,
///        direct or indirect, lies in it; visibility = seen surface voxels / surface voxels.
/// @note Sparse: only the surface voxels are stored (sorted keys), so any resolution works.
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/vdb/box_lattice.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace ivis::optimize {

/// @brief Key of no voxel (a point outside the box).
inline constexpr std::uint64_t kNoVoxel = std::numeric_limits<std::uint64_t>::max();

/// @brief Key (i + n (j + n k)) of the voxel of @a lattice that contains @a p, or kNoVoxel outside the box.
std::uint64_t voxelKey(const vdb::BoxLattice& lattice, const glm::vec3& p);

/// @brief Number of @a keys (sorted and deduplicated in place) that the sorted @a set holds.
std::size_t countIn(const std::vector<std::uint64_t>& set, std::vector<std::uint64_t>& keys);

/// @brief Which surface samples count: a triangle and barycentric weights in, true to keep.
using SampleFilter = std::function<bool(std::size_t triangle, const glm::vec3& barycentric)>;

/// @brief The surface voxels of a mesh (or of the part of it a filter keeps).
class SurfaceVoxels {
public:
    /// @brief Samples every triangle on a lattice of an eighth of a voxel, edges and corners
    ///        included, and keeps the voxels of the samples (that @a keep accepts, when given).
    /// @throw ValueError for a resolution outside 8 to 8192
    SurfaceVoxels(const core::TriangleMesh& mesh, int resolution = 200, const SampleFilter& keep = {});

    /// @brief Key of the voxel containing @a p, or kNoVoxel outside the box.
    std::uint64_t keyOf(const glm::vec3& p) const { return voxelKey(mLattice, p); }
    /// @brief Number of surface voxels among @a keys (sorted and deduplicated in place).
    std::size_t countAmong(std::vector<std::uint64_t>& keys) const;
    /// @brief seen surface voxels / surface voxels for the voxels of @a keys (0 when there are none).
    double fractionSeen(std::vector<std::uint64_t>& keys) const;
    /// @brief The surface voxels split into 26-connected regions, largest first.
    std::vector<std::vector<std::uint64_t>> regions() const;
    /// @brief Number of surface voxels.
    std::size_t count() const { return mKeys.size(); }
    /// @brief The sorted keys.
    const std::vector<std::uint64_t>& keys() const { return mKeys; }
    /// @brief The grid's lattice.
    const vdb::BoxLattice& lattice() const { return mLattice; }

private:
    vdb::BoxLattice mLattice;
    std::vector<std::uint64_t> mKeys;
};

}  // namespace ivis::optimize
