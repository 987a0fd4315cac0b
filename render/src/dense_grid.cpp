#include <ivis/render/dense_grid.h>

#include <ivis/core/errors.h>

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
    mVoxels.resize(std::size_t(dims.x()) * dims.y() * dims.z());
    auto phiAccessor = phi.getConstAccessor();
    auto gradientAccessor = gradient.getConstAccessor();
    std::size_t i = 0;
    for (int z = box.min().z(); z <= box.max().z(); ++z)
        for (int y = box.min().y(); y <= box.max().y(); ++y)
            for (int x = box.min().x(); x <= box.max().x(); ++x) {
                const openvdb::Coord ijk(x, y, z);
                const openvdb::Vec3s g = gradientAccessor.getValue(ijk);
                mVoxels[i++] = glm::vec4(phiAccessor.getValue(ijk), g.x(), g.y(), g.z());
            }
}

}  // namespace ivis::render
