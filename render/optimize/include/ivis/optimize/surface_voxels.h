/// @file surface_voxels.h
/// @brief Surface visibility, the primary measure (docs/measures.md, 1): on a grid of
///        resolution^3 voxels over [-2.5, 2.5]^3 (200 by default), a voxel is a surface voxel when
///        some of the surface's area lies in it, and it is seen when the surface point P of some pixel,
///        direct or indirect, lies in it. Visibility = the surface area inside seen voxels / the
///        whole surface area; the plain count (seen surface voxels / surface voxels) stays beside it.
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

/// @brief How much of a surface some voxels hold, in [0, 1].
struct SurfaceShare {
    double area = 0.0;    ///< surface area inside them / the whole surface area (the visibility)
    double voxels = 0.0;  ///< surface voxels among them / surface voxels (voxel_visibility)
};

/// @brief The surface voxels of a mesh (or of the part of it a filter keeps) and the area inside each.
class SurfaceVoxels {
public:
    /// @brief Cuts every triangle exactly into its pieces inside the voxels (voxel_pieces.h) and
    ///        keeps the voxels holding some area: the area of the pieces in each or, with @a keep,
    ///        each piece's area times the share of it @a keep accepts at 16 even points of each
    ///        triangle of its fan. A voxel holding no area (the surface only touching a face) is none.
    /// @throw ValueError for a resolution outside 8 to 8192
    SurfaceVoxels(const core::TriangleMesh& mesh, int resolution = 200, const SampleFilter& keep = {});

    /// @brief Key of the voxel containing @a p, or kNoVoxel outside the box.
    std::uint64_t keyOf(const glm::vec3& p) const { return voxelKey(mLattice, p); }
    /// @brief Number of surface voxels among @a keys (sorted and deduplicated in place).
    std::size_t countAmong(std::vector<std::uint64_t>& keys) const;
    /// @brief The share of the surface, by area and by voxel count, inside the voxels of @a keys
    ///        (sorted and deduplicated in place; 0 for a surface without voxels or area).
    SurfaceShare shareSeen(std::vector<std::uint64_t>& keys) const;
    /// @brief The surface area inside the voxel of @a key (0 for a voxel the surface misses).
    double areaIn(std::uint64_t key) const;
    /// @brief The surface area inside the box (the sum of areaIn over the surface voxels).
    double totalArea() const { return mTotalArea; }
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
    std::vector<std::uint64_t> mKeys;  ///< sorted keys of the voxels holding surface area
    std::vector<double> mAreas;        ///< the area inside each of mKeys, world units
    double mTotalArea = 0.0;
};

}  // namespace ivis::optimize
