#include "dense_slices.h"

#include <ivis/core/errors.h>
#include <ivis/vdb/surface_volume.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

namespace ivis::app {
namespace {

/// World box of voxel centres of a grid's active bounding box grown by one voxel.
struct WorldBox {
    glm::dvec3 lo{0.0}, hi{0.0};
};

template <typename GridT>
WorldBox activeWorldBox(const GridT& grid)
{
    openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    box.expand(1);
    const openvdb::Vec3d lo = grid.indexToWorld(box.min()), hi = grid.indexToWorld(box.max());
    return {{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}};
}

/// The grid the CPU renderer densifies for far samples: the far field, else the fine band.
const openvdb::FloatGrid& distanceSource(const vdb::SurfaceVolume& volume)
{
    return volume.farPhi ? *volume.farPhi : *volume.phi;
}

/// Dims and first lattice indices of @a box at @a resolution.
void boxLattice(const WorldBox& box, int resolution, std::array<int, 3>& dims, std::array<int, 3>& first)
{
    for (int a = 0; a < 3; ++a) {
        const std::array<int, 2> range = detail::latticeRange(box.lo[a], box.hi[a], resolution);
        first[a] = range[0];
        dims[a] = std::max(1, range[1] - range[0] + 1);
    }
}

template <typename T>
void shapeBox(DenseBox<T>& out, const WorldBox& box, int resolution, std::array<int, 3>& first)
{
    boxLattice(box, resolution, out.dims, first);
    const double voxel = 2.0 * vdb::kBoxHalfExtent / resolution;
    for (int a = 0; a < 3; ++a) out.origin[a] = float(-vdb::kBoxHalfExtent + (first[a] + 0.5) * voxel);
    out.values.assign(out.count(), T{});
}

std::size_t slicesBytes(const WorldBox& far, const WorldBox& band, int resolution, int& largestDim)
{
    std::array<int, 3> d1, d2, f;
    boxLattice(far, resolution, d1, f);
    boxLattice(band, resolution, d2, f);
    largestDim = std::max({d1[0], d1[1], d1[2], d2[0], d2[1], d2[2]});
    return 4 * (std::size_t(d1[0]) * d1[1] * d1[2] + std::size_t(d2[0]) * d2[1] * d2[2]);
}

/// Progress over the slices of both boxes, reported from any thread.
class SliceProgress {
public:
    SliceProgress(core::Interrupter* interrupter, int total) : mInterrupter(interrupter), mTotal(std::max(1, total)) {}
    /// One slice done; true when the user cancelled.
    bool step()
    {
        const int done = ++mDone;
        if (mInterrupter && mInterrupter->wasInterrupted(int(100.0 * done / mTotal))) mCancelled = true;
        return mCancelled;
    }
    bool cancelled() const { return mCancelled; }

private:
    core::Interrupter* mInterrupter;
    int mTotal;
    std::atomic<int> mDone{0};
    std::atomic<bool> mCancelled{false};
};

}  // namespace

std::array<int, 2> detail::latticeRange(double lo, double hi, int resolution)
{
    const double voxel = 2.0 * vdb::kBoxHalfExtent / resolution;
    const double slack = 1e-4;  // in voxels: a centre on the boundary belongs to the box
    int first = int(std::floor((lo + vdb::kBoxHalfExtent) / voxel - 0.5 + slack));
    int last = int(std::ceil((hi + vdb::kBoxHalfExtent) / voxel - 0.5 - slack));
    first = std::clamp(first, 0, resolution - 1);
    last = std::clamp(last, first, resolution - 1);
    return {first, last};
}

std::string DenseSlices::describe() const
{
    char text[512];
    const double mib = double(bytes()) / double(1 << 20), budget = double(budgetBytes) / double(1 << 20);
    if (exact())
        std::snprintf(text, sizeof text,
                      "GPU volume: resolution %d (voxel %.4f), the volume's own; distance %dx%dx%d + triangles "
                      "%dx%dx%d = %.1f MiB of %.0f MiB",
                      shownResolution, voxelSize, distance.dims[0], distance.dims[1], distance.dims[2],
                      triangles.dims[0], triangles.dims[1], triangles.dims[2], mib, budget);
    else
        std::snprintf(text, sizeof text,
                      "GPU volume: resolution %d (voxel %.4f), RESAMPLED from %d to fit %.0f MiB; distance %dx%dx%d "
                      "+ triangles %dx%dx%d = %.1f MiB",
                      shownResolution, voxelSize, volumeResolution, budget, distance.dims[0], distance.dims[1],
                      distance.dims[2], triangles.dims[0], triangles.dims[1], triangles.dims[2], mib);
    return text;
}

int chooseShownResolution(const render::RenderScene& scene, const DenseSliceOptions& options)
{
    const vdb::SurfaceVolume& volume = scene.volume();
    const WorldBox far = activeWorldBox(distanceSource(volume)), band = activeWorldBox(*volume.phi);
    int resolution = volume.options.resolution;
    for (;;) {
        int largest = 0;
        const std::size_t bytes = slicesBytes(far, band, resolution, largest);
        if (bytes <= options.budgetBytes && largest <= options.maxTextureSize) return resolution;
        if (resolution <= 16)
            throw ValueError("the volume textures do not fit " + std::to_string(options.budgetBytes >> 20) +
                             " MiB even at resolution 16");
        // Bytes scale with N^3 and dims with N: jump close to the answer, then creep down.
        const double scale = std::min(std::cbrt(double(options.budgetBytes) / double(bytes)),
                                      double(options.maxTextureSize) / double(largest));
        resolution = std::max(16, std::min(resolution - 1, int(std::floor(resolution * scale * 0.999))));
    }
}

DenseSlices buildDenseSlices(const render::RenderScene& scene, const DenseSliceOptions& options,
                             core::Interrupter* interrupter)
{
    const vdb::SurfaceVolume& volume = scene.volume();
    const render::DistanceField& field = scene.distance();
    DenseSlices slices;
    slices.budgetBytes = options.budgetBytes;
    slices.volumeResolution = volume.options.resolution;
    slices.shownResolution = chooseShownResolution(scene, options);
    slices.voxelSize = float(2.0 * vdb::kBoxHalfExtent / slices.shownResolution);
    slices.reach = field.reach();
    {
        render::DistanceField::Sampler sampler = field.sampler();
        slices.outside = sampler.phi(glm::vec3(1e3f));  // the dense far copy's background
    }
    const bool exact = slices.exact();
    std::array<int, 3> farFirst, bandFirst;
    shapeBox(slices.distance, activeWorldBox(distanceSource(volume)), slices.shownResolution, farFirst);
    shapeBox(slices.triangles, activeWorldBox(*volume.phi), slices.shownResolution, bandFirst);

    if (interrupter) interrupter->start("GPU volume");
    SliceProgress progress(interrupter, slices.distance.dims[2] + slices.triangles.dims[2]);
    const float voxel = slices.voxelSize;

    // Distance: the fine voxel where it is active (exactly what the CPU's fine cells interpolate),
    // else the field's own sample (far field, or background outside every grid).
    DenseBox<float>& distance = slices.distance;
    tbb::parallel_for(tbb::blocked_range<int>(0, distance.dims[2]), [&](const tbb::blocked_range<int>& zs) {
        render::DistanceField::Sampler sampler = field.sampler();
        auto fine = volume.phi->getConstAccessor();
        for (int z = zs.begin(); z != zs.end(); ++z) {
            if (progress.cancelled()) return;
            for (int y = 0; y < distance.dims[1]; ++y)
                for (int x = 0; x < distance.dims[0]; ++x) {
                    const glm::vec3 centre = distance.origin + voxel * glm::vec3(float(x), float(y), float(z));
                    float value;
                    const openvdb::Coord ijk(farFirst[0] + x, farFirst[1] + y, farFirst[2] + z);
                    if (!(exact && fine.probeValue(ijk, value))) value = sampler.phi(centre);
                    distance.values[(std::size_t(z) * distance.dims[1] + y) * distance.dims[0] + x] = value;
                }
            progress.step();
        }
    });

    // Triangles: the grid's own value at its resolution; resampled, the exact closest triangle of
    // every centre near the surface (landing points lie within half a voxel of it).
    DenseBox<std::int32_t>& triangles = slices.triangles;
    const double searchRadius = 2.5 * voxel;
    // Far-field values are within half a coarse voxel of the exact distance.
    const double prefilter = searchRadius + field.voxelSize() + vdb::kBoxHalfExtent / volume.options.farFieldResolution;
    tbb::parallel_for(tbb::blocked_range<int>(0, triangles.dims[2]), [&](const tbb::blocked_range<int>& zs) {
        render::DistanceField::Sampler sampler = field.sampler();
        auto ids = volume.triangle->getConstAccessor();
        for (int z = zs.begin(); z != zs.end(); ++z) {
            if (progress.cancelled()) return;
            for (int y = 0; y < triangles.dims[1]; ++y)
                for (int x = 0; x < triangles.dims[0]; ++x) {
                    std::int32_t id = -1;
                    if (exact) {
                        id = ids.getValue(openvdb::Coord(bandFirst[0] + x, bandFirst[1] + y, bandFirst[2] + z));
                    } else {
                        const glm::vec3 centre = triangles.origin + voxel * glm::vec3(float(x), float(y), float(z));
                        if (std::abs(sampler.phi(centre)) <= prefilter) {
                            int closest = -1;
                            scene.bvh().closestPoint(glm::dvec3(centre), searchRadius, closest);
                            id = closest;
                        }
                    }
                    triangles.values[(std::size_t(z) * triangles.dims[1] + y) * triangles.dims[0] + x] = id;
                }
            progress.step();
        }
    });
    if (interrupter) interrupter->end();
    if (progress.cancelled()) throw Cancelled("GPU volume cancelled");
    return slices;
}

}  // namespace ivis::app
