#include <ivis/render/dense_grid.h>

#include <ivis/core/errors.h>

#include <cmath>
#include <utility>

namespace ivis::render {

float detail::trilinear(const float c[8], const glm::vec3& t, glm::vec3* gradient)
{
    // c[(dx) | (dy << 1) | (dz << 2)]
    const float x00 = c[0] + t.x * (c[1] - c[0]);
    const float x10 = c[2] + t.x * (c[3] - c[2]);
    const float x01 = c[4] + t.x * (c[5] - c[4]);
    const float x11 = c[6] + t.x * (c[7] - c[6]);
    const float y0 = x00 + t.y * (x10 - x00);
    const float y1 = x01 + t.y * (x11 - x01);
    if (gradient) {
        const float dx0 = (c[1] - c[0]) + t.y * ((c[3] - c[2]) - (c[1] - c[0]));
        const float dx1 = (c[5] - c[4]) + t.y * ((c[7] - c[6]) - (c[5] - c[4]));
        gradient->x = dx0 + t.z * (dx1 - dx0);
        gradient->y = (x10 - x00) + t.z * ((x11 - x01) - (x10 - x00));
        gradient->z = y1 - y0;
    }
    return y0 + t.z * (y1 - y0);
}

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

bool DenseGrid::locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const
{
    const glm::vec3 q = (p - mOrigin) * mInvVoxelSize;
    // Inside the box q >= 0, where truncation is floor (and much cheaper than std::floor).
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f)) return false;
    const int ix = int(q.x), iy = int(q.y), iz = int(q.z);
    if (ix >= mDims[0] - 1 || iy >= mDims[1] - 1 || iz >= mDims[2] - 1) return false;
    t = q - glm::vec3(float(ix), float(iy), float(iz));
    base = (std::size_t(iz) * mDims[1] + std::size_t(iy)) * mDims[0] + std::size_t(ix);
    return true;
}

float DenseGrid::value(const glm::vec3& p) const
{
    std::size_t base;
    glm::vec3 t;
    if (!locate(p, base, t)) return mBackground;
    const std::size_t sx = 1, sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const float c[8] = {mValues[base],           mValues[base + sx],           mValues[base + sy],
                        mValues[base + sx + sy], mValues[base + sz],           mValues[base + sx + sz],
                        mValues[base + sy + sz], mValues[base + sx + sy + sz]};
    return detail::trilinear(c, t, nullptr);
}

float DenseGrid::valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const
{
    std::size_t base;
    glm::vec3 t;
    if (!locate(p, base, t)) {
        gradient = glm::vec3(0.0f);
        return mBackground;
    }
    const std::size_t sx = 1, sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const float c[8] = {mValues[base],           mValues[base + sx],           mValues[base + sy],
                        mValues[base + sx + sy], mValues[base + sz],           mValues[base + sx + sz],
                        mValues[base + sy + sz], mValues[base + sx + sy + sz]};
    const float v = detail::trilinear(c, t, &gradient);
    gradient *= mInvVoxelSize;
    return v;
}

}  // namespace ivis::render
