#include <ivis/render/dense_grid.h>

#include <ivis/core/errors.h>

#include <utility>

namespace ivis::render {

DenseGrid::DenseGrid(const openvdb::FloatGrid& grid)
{
    mVoxelSize = float(grid.voxelSize()[0]);
    mInvVoxelSize = 1.0f / mVoxelSize;
    mBackground = grid.background();
    openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    box.expand(1);
    const openvdb::Coord dims = box.dim();
    for (int a = 0; a < 3; ++a) mDims[a] = dims[a];
    const openvdb::Vec3d origin = grid.indexToWorld(box.min());
    mOrigin = glm::vec3(origin.x(), origin.y(), origin.z());
    mValues.resize(std::size_t(dims.x()) * dims.y() * dims.z());
    auto accessor = grid.getConstAccessor();
    std::size_t i = 0;
    for (int z = box.min().z(); z <= box.max().z(); ++z)
        for (int y = box.min().y(); y <= box.max().y(); ++y)
            for (int x = box.min().x(); x <= box.max().x(); ++x) mValues[i++] = accessor.getValue({x, y, z});
}

DenseGrid::DenseGrid(const glm::vec3& origin, const std::array<int, 3>& dims, float voxelSize,
                     std::vector<float> values, float background)
    : mValues(std::move(values)),
      mOrigin(origin),
      mVoxelSize(voxelSize),
      mInvVoxelSize(1.0f / voxelSize),
      mBackground(background)
{
    for (int a = 0; a < 3; ++a) mDims[a] = dims[a];
    IVIS_CHECK(mValues.size() == std::size_t(dims[0]) * dims[1] * dims[2]);
}

}  // namespace ivis::render
