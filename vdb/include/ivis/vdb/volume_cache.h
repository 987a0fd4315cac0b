/// @file volume_cache.h
/// @brief Writes and reads a SurfaceVolume as one .vdb file with validating metadata.
/// @note Files are written to a temporary name in the same folder and renamed into place.
#pragma once

#include <ivis/vdb/surface_volume.h>

#include <string>

namespace ivis::vdb {

/// @brief Version of the on-disk layout; a file with another version is stale.
inline constexpr int kVolumeFormatVersion = 6;

/// @brief What loadOrBuildVolume did.
enum class CacheOutcome { Built, Reused, RebuiltStale, RebuiltCorrupt };

/// @brief Human-readable name of an outcome ("built", "reused", "rebuilt-stale", "rebuilt-corrupt").
const char* toString(CacheOutcome outcome);

/// @brief Writes every grid and the metadata (format version, mesh hash, resolution, band, reach,
///        sign, checksum) atomically.
/// @throw InputError when the file cannot be written (message names the path)
void writeVolume(const SurfaceVolume& volume, const std::string& path);

/// @brief Checks the content checksum that writeVolume appends (its length and hash of the OpenVDB
///        bytes): the first thing readVolume does, before OpenVDB parses a byte.
/// @throw InputError naming the path when the checksum is missing or does not match the content
void checkVolumeChecksum(const std::string& path);

/// @brief Reads a volume written by writeVolume and verifies its checksum.
/// @throw InputError naming the path for a missing, truncated, corrupt or foreign file
SurfaceVolume readVolume(const std::string& path);

/// @brief Reuses the cache at @a path when it matches the mesh and options, else builds the
///        volume and (re)writes the cache; an empty @a path builds and keeps nothing. A corrupt
///        or stale cache is reported and rebuilt.
/// @param reason optional output: why the cache was not reused ("" when reused or absent)
SurfaceVolume loadOrBuildVolume(const core::TriangleMesh& mesh, const VolumeOptions& options,
                                const std::string& path, core::Interrupter* interrupter = nullptr,
                                CacheOutcome* outcome = nullptr, std::string* reason = nullptr);

}  // namespace ivis::vdb
