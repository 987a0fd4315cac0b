/// @file build_memory.h
/// @brief Whether a volume can be built in the memory at hand. OpenVDB's trees allocate as they
///        are freed, so a bad_alloc that unwinds a build with no memory left ends the process
///        (std::terminate; buildSurfaceVolume holds a core::ScopedMemoryReserve against it): a
///        build that cannot fit is refused beforehand.
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/vdb/surface_volume.h>

#include <cstddef>

namespace ivis::vdb {

/// @brief An estimate, from below, of the peak bytes buildSurfaceVolume takes for the normalised
///        @a mesh with @a options: its narrow band's voxels (the surface's area over a voxel's face,
///        times the band's width in voxels) at the bytes per band voxel measured on real meshes.
std::size_t estimatedBuildBytes(const core::TriangleMesh& mesh, const VolumeOptions& options, bool unsignedDistance);

/// @brief The bytes this process may still allocate: the smaller of the system's available memory
///        (/proc/meminfo's MemAvailable) and the address-space limit (RLIMIT_AS, as `ulimit -v`
///        sets it) less what the process maps now; SIZE_MAX when neither is known.
std::size_t allocatableBytes();

/// @brief Refuses a build whose estimated peak exceeds @a available bytes.
/// @throw ValueError "volume resolution N needs about X GiB to build, Y GiB can be allocated: ..."
void checkBuildFits(const core::TriangleMesh& mesh, const VolumeOptions& options, bool unsignedDistance,
                    std::size_t available);

}  // namespace ivis::vdb
