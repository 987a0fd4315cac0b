#include <ivis/vdb/surface_volume.h>

#include <ivis/core/errors.h>

#include <cmath>
#include <malloc.h>
#include <mutex>
#include <string>

namespace ivis::vdb {

void validate(const VolumeOptions& options)
{
    if (options.resolution < kMinResolution || options.resolution > kMaxResolution)
        throw ValueError("volume resolution " + std::to_string(options.resolution) + " is out of range (" +
                         std::to_string(kMinResolution) + " to " + std::to_string(kMaxResolution) + ")");
    if (!(options.bandVoxels >= 3.0f) || !std::isfinite(options.bandVoxels) || options.bandVoxels > 64.0f)
        throw ValueError("narrow band half-width " + std::to_string(options.bandVoxels) +
                         " voxels is out of range (3 to 64)");
    if (!(options.farFieldReach > 0.0) || !std::isfinite(options.farFieldReach) || options.farFieldReach > kMaxFarFieldReach)
        throw ValueError("far-field reach " + std::to_string(options.farFieldReach) + " is out of range (0 to " +
                         std::to_string(int(kMaxFarFieldReach)) + " normalised units)");
    if (options.farFieldResolution < 16 || options.farFieldResolution > 1000)
        throw ValueError("far-field resolution " + std::to_string(options.farFieldResolution) +
                         " is out of range (16 to 1000)");
}

void detail::initializeOpenVdb()
{
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

std::size_t SurfaceVolume::activeVoxels() const
{
    std::size_t count = phi ? phi->activeVoxelCount() : 0;
    if (farPhi) count += farPhi->activeVoxelCount();
    return count;
}

void SurfaceVolume::releaseSampledGrids()
{
    if (released()) return;
    // An empty phi of the same background and transform keeps reach() where phi itself reaches.
    openvdb::FloatGrid::Ptr empty = openvdb::FloatGrid::create(phi->background());
    empty->setTransform(phi->transform().copy());
    empty->setName(phi->getName());
    phi = empty;
    gradient.reset();
#if defined(__GLIBC__)
    // Their pages back to the system: grids read on several threads (readVolume) lie in several
    // malloc arenas, whose free pages the caller's later allocations would not reuse.
    malloc_trim(0);
#endif
}

std::size_t SurfaceVolume::memoryBytes() const
{
    std::size_t bytes = 0;
    if (phi) bytes += phi->memUsage();
    if (triangle) bytes += triangle->memUsage();
    if (gradient) bytes += gradient->memUsage();
    if (farPhi) bytes += farPhi->memUsage();
    if (farGradient) bytes += farGradient->memUsage();
    return bytes;
}

double SurfaceVolume::reach() const
{
    if (farPhi) return options.farFieldReach;
    return phi ? double(phi->background()) : 0.0;
}

}  // namespace ivis::vdb
