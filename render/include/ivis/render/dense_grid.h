/// @file dense_grid.h
/// @brief A dense float copy of a sparse grid's active region, sampled trilinearly with the
///        analytic gradient of the trilinear cell (the fast path for far-field distances).
#pragma once

#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace ivis::render {

/// @brief Dense box of voxel values; outside the box every sample is the background value.
class DenseGrid {
public:
    DenseGrid() = default;
    /// @brief Copies the active bounding box (plus one voxel) of @a grid; inactive voxels keep
    ///        their (signed) background value.
    explicit DenseGrid(const openvdb::FloatGrid& grid);
    /// @brief Adopts @a values (x fastest, then y, then z) of a box of @a dims voxels whose voxel
    ///        (0,0,0) is centred at @a origin.
    DenseGrid(const glm::vec3& origin, const std::array<int, 3>& dims, float voxelSize, std::vector<float> values,
              float background);

    /// @brief Trilinear value at world point p (background outside the box).
    float value(const glm::vec3& p) const;
    /// @brief Trilinear value and its exact gradient within the cell containing p.
    float valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const;
    /// @brief World-space voxel size.
    float voxelSize() const { return mVoxelSize; }
    /// @brief Value used outside the box.
    float background() const { return mBackground; }
    /// @brief Bytes held by the value array.
    std::size_t memoryBytes() const { return mValues.size() * sizeof(float); }

private:
    /// Cell origin index and fractional position of p; false when the cell is outside the box.
    bool locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const;
    /// The 8 corner values of the cell whose origin index is @a base, c[zyx bits].
    void corners(std::size_t base, float c[8]) const;

    std::vector<float> mValues;
    int mDims[3] = {0, 0, 0};
    glm::vec3 mOrigin{0.0f};  ///< world position of voxel (0,0,0) of the box
    float mVoxelSize = 1.0f;
    float mInvVoxelSize = 1.0f;
    float mBackground = 0.0f;
};

namespace detail {
/// @brief Trilinear interpolation of 8 corner values c[zyx bits] at fractions t, with gradient
///        (in index units) written to @a gradient when not null.
inline float trilinear(const float c[8], const glm::vec3& t, glm::vec3* gradient)
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
}  // namespace detail

// The samplers below are inline: curved rays call them at every step.

inline bool DenseGrid::locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const
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

inline void DenseGrid::corners(std::size_t base, float c[8]) const
{
    const std::size_t sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const float* v = mValues.data() + base;
    c[0] = v[0];
    c[1] = v[1];
    c[2] = v[sy];
    c[3] = v[sy + 1];
    c[4] = v[sz];
    c[5] = v[sz + 1];
    c[6] = v[sz + sy];
    c[7] = v[sz + sy + 1];
}

inline float DenseGrid::value(const glm::vec3& p) const
{
    std::size_t base;
    glm::vec3 t;
    if (!locate(p, base, t)) return mBackground;
    float c[8];
    corners(base, c);
    return detail::trilinear(c, t, nullptr);
}

inline float DenseGrid::valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const
{
    std::size_t base;
    glm::vec3 t;
    if (!locate(p, base, t)) {
        gradient = glm::vec3(0.0f);
        return mBackground;
    }
    float c[8];
    corners(base, c);
    const float v = detail::trilinear(c, t, &gradient);
    gradient *= mInvVoxelSize;
    return v;
}

}  // namespace ivis::render
