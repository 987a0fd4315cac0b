#include <ivis/vdb/build_memory.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace ivis::vdb {
namespace {

/// Peak bytes per narrow-band voxel of a build (the distance, closest-triangle and gradient grids
/// and OpenVDB's intermediate trees): the growth of the peak resident memory (`/usr/bin/time -f %M
/// inversevis sdf MESH --volume-res N`) over the growth of the band's voxels from N = 1000 to 1500
/// was 30.2 bytes on the Stanford bunny (47.7 while the volume still held barycentrics, when the
/// armadillo's was 61 and the VaMPy artery's 58.7); rounded down, and the process's other
/// 110-130 MB left out, so that the estimate stays below the peak.
constexpr double kBuildBytesPerBandVoxel = 28.0;

}  // namespace

std::size_t estimatedBuildBytes(const core::TriangleMesh& mesh, const VolumeOptions& options, bool unsignedDistance)
{
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    const NarrowBandWidth band = narrowBandWidth(options, unsignedDistance);
    const double voxel = 2.0 * kBoxHalfExtent / options.resolution;
    const double bandVoxels = area / (voxel * voxel) * double(band.exterior + band.interior);
    return std::size_t(kBuildBytesPerBandVoxel * bandVoxels);
}

std::size_t allocatableBytes()
{
    std::size_t bytes = std::numeric_limits<std::size_t>::max();
    std::ifstream meminfo("/proc/meminfo");
    for (std::string key; meminfo >> key;) {
        std::size_t kilobytes = 0;
        std::string unit;
        if (!(meminfo >> kilobytes >> unit)) break;
        if (key == "MemAvailable:") bytes = std::min(bytes, kilobytes * 1024);
    }
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
        std::size_t mappedPages = 0;
        std::ifstream("/proc/self/statm") >> mappedPages;
        const std::size_t mapped = mappedPages * std::size_t(sysconf(_SC_PAGESIZE));
        bytes = std::min(bytes, limit.rlim_cur > mapped ? std::size_t(limit.rlim_cur) - mapped : std::size_t(0));
    }
    return bytes;
}

void checkBuildFits(const core::TriangleMesh& mesh, const VolumeOptions& options, bool unsignedDistance,
                    std::size_t available)
{
    const std::size_t needed = estimatedBuildBytes(mesh, options, unsignedDistance);
    if (needed <= available) return;
    // The band's voxels grow with the square of the resolution, or faster: this resolution fits.
    const int fits = int(options.resolution * std::sqrt(double(available) / double(needed)));
    char text[240];
    std::snprintf(text, sizeof text,
                  "volume resolution %d needs about %.1f GiB to build, %.1f GiB can be allocated: lower "
                  "--volume-res (at most about %d)",
                  options.resolution, double(needed) / (1 << 30), double(available) / (1 << 30), fits);
    throw ValueError(text);
}

}  // namespace ivis::vdb
