#include <ivis/render/dense_grid.h>

#include <ivis/core/errors.h>

#include <tbb/parallel_for.h>

namespace ivis::render {

DenseGrid::DenseGrid(const openvdb::FloatGrid& phi, const openvdb::Vec3SGrid& gradient)
{
    IVIS_CHECK(phi.tree().hasSameTopology(gradient.tree()));
    mVoxelSize = float(phi.voxelSize()[0]);
    mInvVoxelSize = 1.0f / mVoxelSize;
    mBackground = phi.background();
    openvdb::CoordBBox box = phi.evalActiveVoxelBoundingBox();
    box.expand(1);
    const openvdb::Coord dims = box.dim();
    for (int a = 0; a < 3; ++a) mDims[a] = dims[a];
    const openvdb::Vec3d origin = phi.indexToWorld(box.min());
    mOrigin = glm::vec3(origin.x(), origin.y(), origin.z());
    const std::size_t count = std::size_t(dims.x()) * dims.y() * dims.z();
    mVoxels = core::makeLargeBlockArray<glm::vec4>(count);  // filled below, slab by slab in parallel, never zeroed first
    tbb::parallel_for(box.min().z(), box.max().z() + 1, [&](int z) {
        auto phiAccessor = phi.getConstAccessor();
        auto gradientAccessor = gradient.getConstAccessor();
        std::size_t i = std::size_t(z - box.min().z()) * dims.x() * dims.y();
        for (int y = box.min().y(); y <= box.max().y(); ++y)
            for (int x = box.min().x(); x <= box.max().x(); ++x) {
                const openvdb::Coord ijk(x, y, z);
                const openvdb::Vec3s g = gradientAccessor.getValue(ijk);
                mVoxels[i++] = glm::vec4(phiAccessor.getValue(ijk), g.x(), g.y(), g.z());
            }
    });
}

}  // namespace ivis::render
