#include "dense_slices.h"

#include <ivis/core/errors.h>
#include <ivis/render/method_registry.h>
#include <ivis/vdb/surface_volume.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <functional>

namespace ivis::app {
namespace {

/// World box of the voxel centres of a grid's active bounding box grown by one voxel (the box
/// render::DenseGrid copies).
struct WorldBox {
    glm::dvec3 lo{0.0}, hi{0.0};
};

WorldBox activeWorldBox(const openvdb::FloatGrid& grid)
{
    openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    box.expand(1);
    const openvdb::Vec3d lo = grid.indexToWorld(box.min()), hi = grid.indexToWorld(box.max());
    return {{lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()}};
}

/// Dims and first lattice indices of @a box at @a resolution.
void boxLattice(const WorldBox& box, int resolution, std::array<int, 3>& dims, std::array<int, 3>& first)
{
    for (int a = 0; a < 3; ++a) {
        const std::array<int, 2> range = detail::latticeRange(box.lo[a], box.hi[a], resolution);
        first[a] = range[0];
        dims[a] = range[1] - range[0] + 1;
    }
}

std::size_t voxelCount(const WorldBox& box, int resolution, int& largestDim)
{
    std::array<int, 3> dims, first;
    boxLattice(box, resolution, dims, first);
    largestDim = std::max({largestDim, dims[0], dims[1], dims[2]});
    return std::size_t(dims[0]) * dims[1] * dims[2];
}

template <typename T>
std::array<int, 3> shapeBox(DenseBox<T>& out, const WorldBox& box, int resolution)
{
    std::array<int, 3> first;
    boxLattice(box, resolution, out.dims, first);
    const vdb::BoxLattice lattice{resolution};
    for (int a = 0; a < 3; ++a) out.origin[a] = float(lattice.worldFromIndex(first[a]));
    out.values.assign(out.count(), T{});
    return first;
}

/// Runs @a slice(z, sampler) for every z slice of a box in parallel, reporting progress.
class SliceRunner {
public:
    SliceRunner(core::Interrupter* interrupter, int totalSlices)
        : mInterrupter(interrupter), mTotal(std::max(1, totalSlices))
    {
    }
    void run(const render::DistanceField& field, int slices,
             const std::function<void(int, render::DistanceField::Sampler&)>& slice)
    {
        tbb::parallel_for(tbb::blocked_range<int>(0, slices), [&](const tbb::blocked_range<int>& zs) {
            render::DistanceField::Sampler sampler = field.sampler();
            for (int z = zs.begin(); z != zs.end(); ++z) {
                if (mCancelled) return;
                slice(z, sampler);
                const int done = ++mDone;
                if (mInterrupter && mInterrupter->wasInterrupted(int(100.0 * done / mTotal))) mCancelled = true;
            }
        });
    }
    bool cancelled() const { return mCancelled; }

private:
    core::Interrupter* mInterrupter;
    int mTotal;
    std::atomic<int> mDone{0};
    std::atomic<bool> mCancelled{false};
};

/// (phi, gradient) of voxel @a ijk of a distance grid and its gradient grid.
glm::vec4 voxelSample(openvdb::FloatGrid::ConstAccessor& phi, openvdb::Vec3SGrid::ConstAccessor& gradient,
                      const openvdb::Coord& ijk)
{
    const openvdb::Vec3s g = gradient.getValue(ijk);
    return {phi.getValue(ijk), g.x(), g.y(), g.z()};
}

/// (phi, gradient) of the CPU's distance field at @a p.
glm::vec4 fieldSample(render::DistanceField::Sampler& sampler, const glm::vec3& p)
{
    glm::vec3 gradient;
    const float phi = sampler.phiAndGradient(p, gradient);
    return {phi, gradient};
}

template <typename T>
std::size_t indexOf(const DenseBox<T>& box, int x, int y, int z)
{
    return (std::size_t(z) * box.dims[1] + y) * box.dims[0] + x;
}

}  // namespace

std::array<int, 2> detail::latticeRange(double lo, double hi, int resolution)
{
    const vdb::BoxLattice lattice{resolution};
    const double slack = 1e-4;  // in voxels: a centre on the boundary belongs to the box
    int first = int(std::floor(lattice.indexFromWorld(lo) + slack));
    int last = int(std::ceil(lattice.indexFromWorld(hi) - slack));
    first = std::clamp(first, 0, resolution - 1);
    last = std::clamp(last, first, resolution - 1);
    return {first, last};
}

std::string DenseSlices::describe() const
{
    char text[640];
    const double mib = double(bytes()) / double(1 << 20), budget = double(budgetBytes) / double(1 << 20);
    const std::string farText = hasFineBand ? ", far field at " + std::to_string(farResolution) : "";
    if (exact())
        std::snprintf(text, sizeof text,
                      "GPU volume: resolution %d (voxel %.4f), the volume's own%s; %.1f MiB of %.0f MiB", shownResolution,
                      voxelSize, farText.c_str(), mib, budget);
    else
        std::snprintf(text, sizeof text,
                      "GPU volume: resolution %d (voxel %.4f), RESAMPLED from %d to fit %.0f MiB%s; %.1f MiB",
                      shownResolution, voxelSize, volumeResolution, budget, farText.c_str(), mib);
    return text;
}

int chooseShownResolution(const render::RenderScene& scene, const DenseSliceOptions& options)
{
    const vdb::SurfaceVolume& volume = scene.volume();
    const WorldBox band = activeWorldBox(*volume.phi);
    int farLargest = 0;
    std::size_t farCount = 0;
    if (volume.farPhi) farCount = voxelCount(activeWorldBox(*volume.farPhi), volume.options.farFieldResolution, farLargest);
    int resolution = volume.options.resolution;
    for (;;) {
        int largest = farLargest;
        // Per band voxel 20 bytes: band (phi, gradient) + triangle, or (without a far field) far copy
        // + triangle; per far voxel 16 bytes.
        const std::size_t bytes = 16 * farCount + 20 * voxelCount(band, resolution, largest);
        if (bytes <= options.budgetBytes && largest <= options.maxTextureSize) return resolution;
        if (resolution <= 16) {
            char text[400];
            if (farLargest > options.maxTextureSize)
                std::snprintf(text, sizeof text,
                              "the far field's textures are %d voxels across, more than the GPU's largest 3D texture "
                              "(%d): lower --reach",
                              farLargest, options.maxTextureSize);
            else if (16 * farCount > options.budgetBytes)
                std::snprintf(text, sizeof text,
                              "the volume textures need %.1f MiB even at resolution 16, more than --texture-budget %zu "
                              "MiB: the far field (reach %g) alone takes %.1f MiB; raise the budget or lower --reach",
                              double(bytes) / double(1 << 20), options.budgetBytes >> 20,
                              volume.options.farFieldReach, double(16 * farCount) / double(1 << 20));
            else
                std::snprintf(text, sizeof text,
                              "the volume textures need %.1f MiB even at resolution 16, more than --texture-budget %zu MiB",
                              double(bytes) / double(1 << 20), options.budgetBytes >> 20);
            throw ValueError(text);
        }
        // Bytes scale with N^3 and dims with N: jump close to the answer, then creep down.
        const double room = double(options.budgetBytes) - 16.0 * double(farCount);
        const double scale = std::min(std::cbrt(std::max(room, 1.0) / double(bytes - 16 * farCount)),
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
    slices.voxelSize = float(vdb::BoxLattice{slices.shownResolution}.voxelSize());
    slices.hasFineBand = bool(volume.farPhi);
    slices.reach = field.reach();
    for (const render::MethodInfo* info : render::methodRegistry())
        for (const render::VertexArrayMaker& make : info->vertexArrays)
            slices.methodArrays[info->name].push_back(make(scene));
    slices.unsignedDistance = field.isUnsigned();
    const openvdb::FloatGrid& farSource = volume.farPhi ? *volume.farPhi : *volume.phi;
    const openvdb::Vec3SGrid& farGradient = volume.farPhi ? *volume.farGradient : *volume.gradient;
    slices.outside = farSource.background();
    slices.farResolution = volume.farPhi ? volume.options.farFieldResolution : slices.shownResolution;
    slices.farVoxelSize = float(vdb::BoxLattice{slices.farResolution}.voxelSize());
    slices.fineFrom = field.fineFrom();
    slices.fineUntil = field.fineUntil();
    const bool exact = slices.exact();
    const WorldBox bandBox = activeWorldBox(*volume.phi);

    const std::array<int, 3> farFirst = shapeBox(slices.far, activeWorldBox(farSource), slices.farResolution);
    std::array<int, 3> bandFirst{0, 0, 0};
    if (slices.hasFineBand) bandFirst = shapeBox(slices.band, bandBox, slices.shownResolution);
    const std::array<int, 3> triangleFirst = shapeBox(slices.triangles, bandBox, slices.shownResolution);

    if (interrupter) interrupter->start("GPU volume");
    SliceRunner runner(interrupter, slices.far.dims[2] + slices.band.dims[2] + slices.triangles.dims[2]);

    // Far copy: render::DenseGrid's voxels (phi and gradient of the source grids); resampled only
    // without a far field.
    DenseBox<glm::vec4>& far = slices.far;
    const bool farIsCopy = slices.hasFineBand || exact;
    runner.run(field, far.dims[2], [&](int z, render::DistanceField::Sampler& sampler) {
        auto phis = farSource.getConstAccessor();
        auto gradients = farGradient.getConstAccessor();
        for (int y = 0; y < far.dims[1]; ++y)
            for (int x = 0; x < far.dims[0]; ++x) {
                const openvdb::Coord ijk(farFirst[0] + x, farFirst[1] + y, farFirst[2] + z);
                const glm::vec3 centre = far.origin + slices.farVoxelSize * glm::vec3(float(x), float(y), float(z));
                far.values[indexOf(far, x, y, z)] = farIsCopy ? voxelSample(phis, gradients, ijk) : fieldSample(sampler, centre);
            }
    });

    // Fine band: the voxel where it is active; resampled, the field where the fine cell is in the band.
    DenseBox<glm::vec4>& band = slices.band;
    const float fineVoxel = float(volume.lattice().voxelSize());
    const glm::vec3 fineOrigin(float(volume.lattice().worldFromIndex(0.0)));
    runner.run(field, band.dims[2], [&](int z, render::DistanceField::Sampler& sampler) {
        auto accessor = volume.phi->getConstAccessor();
        auto gradients = volume.gradient->getConstAccessor();
        for (int y = 0; y < band.dims[1]; ++y)
            for (int x = 0; x < band.dims[0]; ++x) {
                glm::vec4 value(kInactiveBandValue, 0.0f, 0.0f, 0.0f);
                if (exact) {
                    const openvdb::Coord ijk(bandFirst[0] + x, bandFirst[1] + y, bandFirst[2] + z);
                    if (accessor.isValueOn(ijk)) value = voxelSample(accessor, gradients, ijk);
                } else {
                    const glm::vec3 centre = band.origin + slices.voxelSize * glm::vec3(float(x), float(y), float(z));
                    const glm::vec3 q = (centre - fineOrigin) / fineVoxel;
                    const openvdb::Coord base(int(std::floor(q.x)), int(std::floor(q.y)), int(std::floor(q.z)));
                    bool inBand = true;
                    for (int i = 0; i < 8 && inBand; ++i)
                        inBand = accessor.isValueOn(base.offsetBy(i & 1, (i >> 1) & 1, (i >> 2) & 1));
                    if (inBand) value = fieldSample(sampler, centre);
                }
                band.values[indexOf(band, x, y, z)] = value;
            }
    });

    // Triangles: the grid's own value; resampled, the exact closest triangle of every centre near the
    // surface (landing points lie within half a voxel of it).
    DenseBox<std::int32_t>& triangles = slices.triangles;
    const double searchRadius = 2.5 * slices.voxelSize;
    // Far-field values are within half a coarse voxel of the exact distance.
    const double prefilter = searchRadius + fineVoxel + 0.5 * slices.farVoxelSize;
    runner.run(field, triangles.dims[2], [&](int z, render::DistanceField::Sampler& sampler) {
        auto ids = volume.triangle->getConstAccessor();
        for (int y = 0; y < triangles.dims[1]; ++y)
            for (int x = 0; x < triangles.dims[0]; ++x) {
                std::int32_t id = -1;
                if (exact) {
                    id = ids.getValue(openvdb::Coord(triangleFirst[0] + x, triangleFirst[1] + y, triangleFirst[2] + z));
                } else {
                    const glm::vec3 centre = triangles.origin + slices.voxelSize * glm::vec3(float(x), float(y), float(z));
                    if (std::abs(sampler.phi(centre)) <= prefilter) {
                        int closest = -1;
                        scene.bvh().closestPoint(glm::dvec3(centre), searchRadius, closest);
                        id = closest;
                    }
                }
                triangles.values[indexOf(triangles, x, y, z)] = id;
            }
    });
    if (interrupter) interrupter->end();
    if (runner.cancelled()) throw Cancelled("GPU volume cancelled");
    return slices;
}

}  // namespace ivis::app
