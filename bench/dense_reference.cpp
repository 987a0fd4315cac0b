#include "dense_reference.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace ivis::bench {

DenseReference::DenseReference(const render::RenderScene& scene)
{
    const vdb::SurfaceVolume& volume = scene.volume();
    const openvdb::FloatGrid& reachGrid = volume.farPhi ? *volume.farPhi : *volume.phi;
    const openvdb::CoordBBox box = reachGrid.evalActiveVoxelBoundingBox();
    const openvdb::Vec3d lo = reachGrid.indexToWorld(box.min()), hi = reachGrid.indexToWorld(box.max());
    const vdb::BoxLattice lattice = volume.lattice();
    const float voxel = float(lattice.voxelSize());
    mInvVoxelSize = 1.0f / voxel;
    mBackground = scene.distance().reach();
    // Aligned to the fine grid's voxel centres.
    for (int a = 0; a < 3; ++a) {
        const int first = int(std::floor(lattice.indexFromWorld(lo[a])));
        const int last = int(std::ceil(lattice.indexFromWorld(hi[a])));
        mOrigin[a] = float(lattice.worldFromIndex(first));
        mDims[a] = last - first + 1;
    }
    mValues.resize(std::size_t{1} * mDims[0] * mDims[1] * mDims[2]);
    tbb::parallel_for(0, mDims[2], [&](int z) {
        auto sampler = scene.distance().sampler();
        std::size_t i = std::size_t(z) * mDims[1] * mDims[0];
        for (int y = 0; y < mDims[1]; ++y)
            for (int x = 0; x < mDims[0]; ++x)
                mValues[i++] = sampler.phi(mOrigin + voxel * glm::vec3(float(x), float(y), float(z)));
    });
}

float DenseReference::phiAndGradient(const glm::vec3& p, glm::vec3& gradient) const
{
    const glm::vec3 q = (p - mOrigin) * mInvVoxelSize;
    gradient = glm::vec3(0.0f);
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f)) return mBackground;
    const int ix = int(q.x), iy = int(q.y), iz = int(q.z);
    if (ix >= mDims[0] - 1 || iy >= mDims[1] - 1 || iz >= mDims[2] - 1) return mBackground;
    const glm::vec3 t = q - glm::vec3(float(ix), float(iy), float(iz));
    const std::size_t sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const float* v = mValues.data() + (std::size_t(iz) * mDims[1] + std::size_t(iy)) * mDims[0] + std::size_t(ix);
    const float c[8] = {v[0], v[1], v[sy], v[sy + 1], v[sz], v[sz + 1], v[sz + sy], v[sz + sy + 1]};
    const float x00 = c[0] + t.x * (c[1] - c[0]), x10 = c[2] + t.x * (c[3] - c[2]);
    const float x01 = c[4] + t.x * (c[5] - c[4]), x11 = c[6] + t.x * (c[7] - c[6]);
    const float y0 = x00 + t.y * (x10 - x00), y1 = x01 + t.y * (x11 - x01);
    const float dx0 = (c[1] - c[0]) + t.y * ((c[3] - c[2]) - (c[1] - c[0]));
    const float dx1 = (c[5] - c[4]) + t.y * ((c[7] - c[6]) - (c[5] - c[4]));
    gradient = mInvVoxelSize *
               glm::vec3(dx0 + t.z * (dx1 - dx0), (x10 - x00) + t.z * ((x11 - x01) - (x10 - x00)), y1 - y0);
    return y0 + t.z * (y1 - y0);
}

}  // namespace ivis::bench
