/// @file surface_volume.h
/// @brief The sparse volume of a surface: narrow-band distance, closest triangle and exact
///        distance gradient, plus a coarse far field (distance and gradient) reaching the
///        InverseVis hull.
/// @note OpenVDB sign convention: phi < 0 inside, phi > 0 outside; open meshes store |distance|.
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/core/triangle_mesh.h>
#include <ivis/vdb/box_lattice.h>

#include <openvdb/openvdb.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace ivis::vdb {

/// @brief Volume resolutions accepted by validate() (voxels across the box).
inline constexpr int kMinResolution = 16;
/// @brief See kMinResolution.
inline constexpr int kMaxResolution = 4096;

/// @brief Whether the distance carries an inside/outside sign.
enum class DistanceSign {
    Auto,     ///< signed for closed meshes, unsigned when boundary edges exist
    Signed,   ///< force signed (the mesh must be closed for a meaningful sign)
    Unsigned  ///< force unsigned
};

/// @brief The largest far-field reach a volume takes (normalised units).
inline constexpr double kMaxFarFieldReach = 2.0;

/// @brief Build parameters; all lengths are in normalised units unless the name says voxels.
struct VolumeOptions {
    int resolution = 200;            ///< voxels across [-2.5,2.5] (voxel size 5/resolution)
    float bandVoxels = 3.0f;         ///< half-width of the fine narrow band, in fine voxels
    double farFieldReach = 0.6;      ///< exterior distance covered by the far field (hull 0.4 + margin)
    int farFieldResolution = 200;    ///< resolution of the coarse far-field grid (paper: 200)
    DistanceSign sign = DistanceSign::Auto;
};

/// @brief Checks an options struct; throws ValueError naming the bad value.
void validate(const VolumeOptions& options);

/// @brief Grids of one surface at one resolution. Every grid's transform is its BoxLattice's:
///        voxel centre i sits at -2.5 + (i + 0.5) * voxelSize.
struct SurfaceVolume {
    /// Fine narrow band: exact distance to the closest triangle (background: +band width, world units).
    openvdb::FloatGrid::Ptr phi;
    /// Closest triangle index per active phi voxel (background -1 = none).
    openvdb::Int32Grid::Ptr triangle;
    /// Exact gradient of phi per active phi voxel: the unit vector from the closest point, times the
    /// sign of phi (the triangle's normal on the surface itself); background 0.
    openvdb::Vec3SGrid::Ptr gradient;
    /// Coarse exterior distance reaching farFieldReach, exact at every voxel; null when phi itself
    /// reaches that far.
    openvdb::FloatGrid::Ptr farPhi;
    /// Exact gradient of farPhi per active voxel, as @a gradient; null with farPhi.
    openvdb::Vec3SGrid::Ptr farGradient;

    VolumeOptions options;
    bool unsignedDistance = false;  ///< true when phi is |distance| (open meshes)
    std::uint64_t meshHash = 0;     ///< core::meshHash of the normalised mesh it was built from
    std::size_t triangleCount = 0;  ///< triangles of that mesh

    /// @brief Frees the fine band's phi and gradient grids (most of the volume's
    ///        memory), keeping the triangle grid, the far field, the options and reach():
    ///        what a renderer still reads once it has copied the distances it samples
    ///        (render::DistanceField). For a program that only renders from it.
    void releaseSampledGrids();
    /// @brief Whether releaseSampledGrids() has emptied it (no renderer can be built from it then).
    bool released() const { return !gradient; }

    /// @brief Lattice of the fine grids (phi, triangle, gradient).
    BoxLattice lattice() const { return {options.resolution}; }
    /// @brief Lattice of the far field (farPhi).
    BoxLattice farLattice() const { return {options.farFieldResolution}; }
    /// @brief Fine voxel size in normalised units.
    double voxelSize() const { return lattice().voxelSize(); }
    /// @brief Active voxels over all grids' distance fields (phi + farPhi).
    std::size_t activeVoxels() const;
    /// @brief Memory held by all grids, in bytes.
    std::size_t memoryBytes() const;
    /// @brief Exterior distance up to which phi or farPhi is exact (normalised units).
    double reach() const;
};

/// @brief Builds the volume of a normalised mesh (positions within [-1,1]^3).
/// @param mesh normalised triangle mesh (caps included; cap triangles get IDs like any other)
/// @param options resolution, band, far field and sign
/// @param interrupter optional progress/cancel callback
/// @throw ValueError for bad options or an empty mesh; Cancelled if interrupted
/// @warning Uses all TBB threads; the result does not depend on the thread count.
SurfaceVolume buildSurfaceVolume(const core::TriangleMesh& mesh, const VolumeOptions& options,
                                 core::Interrupter* interrupter = nullptr);

/// @brief The fine narrow band's half-widths in voxels, outside and inside the surface.
struct NarrowBandWidth {
    float exterior = 0.0f;
    float interior = 0.0f;
};

/// @brief The band buildSurfaceVolume builds under @a options: outside, as far as the hull when its
///        voxels are as coarse as the far field's, else a far voxel and two fine ones (within a far
///        voxel of the surface the far field's blend is poor, and the renderer passes from band to
///        far field beyond that, render::DistanceField); inside, options.bandVoxels, or as outside
///        for an unsigned distance.
NarrowBandWidth narrowBandWidth(const VolumeOptions& options, bool unsignedDistance);

/// @brief OpenVDB's plain mesh-to-volume conversion on the box grid of @a resolution (the first
///        stage of buildSurfaceVolume, and the benchmark reference).
/// @param exteriorVoxels, interiorVoxels band half-widths in voxels
/// @param indexGrid optional output: closest-polygon index per band voxel (background -1)
/// @return distance grid, background +exterior width (world units)
/// @throw Cancelled if interrupted
openvdb::FloatGrid::Ptr meshToNarrowBand(const core::TriangleMesh& mesh, int resolution, float exteriorVoxels,
                                         float interiorVoxels, bool unsignedDistance,
                                         core::Interrupter* interrupter = nullptr,
                                         openvdb::Int32Grid* indexGrid = nullptr);

/// @brief Whether the mesh gets an unsigned distance under @a sign (Auto: open mesh -> unsigned).
bool usesUnsignedDistance(const core::TriangleMesh& mesh, DistanceSign sign);

namespace detail {
/// @brief Registers OpenVDB's grid types once per process (thread-safe, idempotent).
void initializeOpenVdb();
}  // namespace detail

}  // namespace ivis::vdb
