/// @file dense_grid.h
/// @brief A dense copy of a sparse distance grid's active region with the exact gradient stored per
///        voxel, sampled by detail::blend: a gradient continuous across voxel faces (so curved rays
///        bend smoothly) and a phi consistent with it.
#pragma once

#include <ivis/core/huge_page_allocator.h>

#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ivis::render {

/// @brief Dense box of voxels (phi, exact gradient); outside the box every sample is the
///        background value with a zero gradient.
class DenseGrid {
public:
    DenseGrid() = default;
    /// @brief Copies the active bounding box (plus one voxel) of @a phi and @a gradient (same
    ///        topology); inactive voxels keep their (signed) background value and a zero gradient.
    DenseGrid(const openvdb::FloatGrid& phi, const openvdb::Vec3SGrid& gradient);

    /// @brief detail::blend's phi and gradient at world point p (background and a zero gradient
    ///        outside the box).
    float valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const;
    /// @brief World-space voxel size.
    float voxelSize() const { return mVoxelSize; }

private:
    /// Cell origin index and fractional position of p; false when the cell is outside the box.
    bool locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const;

    core::HugePageArray<glm::vec4> mVoxels;  ///< (phi, gradient) per voxel, x fastest, then y, then z
    int mDims[3] = {0, 0, 0};
    glm::vec3 mOrigin{0.0f};  ///< world position of voxel (0,0,0) of the box
    float mVoxelSize = 1.0f;
    float mInvVoxelSize = 1.0f;
    float mBackground = 0.0f;
};

namespace detail {
/// @brief Trilinear weights of the 8 corners c[dx | dy << 1 | dz << 2] of a cell at fractions t.
inline void trilinearWeights(const glm::vec3& t, float w[8])
{
    const float x0 = 1.0f - t.x, y0 = 1.0f - t.y, z0 = 1.0f - t.z;
    const float a = x0 * y0, b = t.x * y0, c = x0 * t.y, d = t.x * t.y;
    w[0] = a * z0, w[1] = b * z0, w[2] = c * z0, w[3] = d * z0;
    w[4] = a * t.z, w[5] = b * t.z, w[6] = c * t.z, w[7] = d * t.z;
}

/// @brief The blend of the 8 corner samples corner(i), i = dx | dy << 1 | dz << 2, each (phi, exact
///        gradient), of a cell of size @a voxelSize at fractions @a t: the gradient is the trilinear
///        blend of the corners' gradients, phi the trilinear blend of each corner's first-order
///        Taylor extrapolation phi_i + g_i . (p - x_i) (exact for a plane, and its derivative is the
///        blended gradient up to O(h^2), so that phi and the force the rays feel agree). With SSE2
///        the four components are summed in one register, each by the same operations in the same
///        order as without it, so that both give the same bits.
template <typename Corner>
[[gnu::always_inline]] inline glm::vec4 blendCorners(Corner corner, const glm::vec3& t, float voxelSize)
{
    float w[8];
    trilinearWeights(t, w);
    float towardsCorner = 0.0f;  // sum of w_i g_i . d_i, d_i the corner's offset in the cell
#if defined(__SSE2__)
    __m128 total = _mm_setzero_ps();
#else
    glm::vec4 total(0.0f);
#endif
    for (int i = 0; i < 8; ++i) {
        const glm::vec4& c = corner(i);
#if defined(__SSE2__)
        total = _mm_add_ps(total, _mm_mul_ps(_mm_set1_ps(w[i]), _mm_loadu_ps(&c.x)));
#else
        total += w[i] * c;
#endif
        towardsCorner += w[i] * ((i & 1 ? c.y : 0.0f) + (i & 2 ? c.z : 0.0f) + (i & 4 ? c.w : 0.0f));
    }
#if defined(__SSE2__)
    glm::vec4 sum;
    _mm_storeu_ps(&sum.x, total);
#else
    glm::vec4 sum = total;
#endif
    sum.x += voxelSize * (sum.y * t.x + sum.z * t.y + sum.w * t.z - towardsCorner);
    return sum;
}

/// @brief blendCorners of the corners c[dx | dy << 1 | dz << 2].
inline glm::vec4 blend(const glm::vec4 c[8], const glm::vec3& t, float voxelSize)
{
    return blendCorners([c](int i) -> const glm::vec4& { return c[i]; }, t, voxelSize);
}

/// @brief blendCorners of the cell whose corner (0, 0, 0) is @a v, its rows @a sy and its slices
///        @a sz voxels apart in memory.
[[gnu::always_inline]] inline glm::vec4 blendCell(const glm::vec4* v, std::size_t sy, std::size_t sz, const glm::vec3& t,
                                                  float voxelSize)
{
    return blendCorners([v, sy, sz](int i) -> const glm::vec4& { return v[(i & 1) + (i & 2 ? sy : 0) + (i & 4 ? sz : 0)]; },
                        t, voxelSize);
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

inline float DenseGrid::valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const
{
    std::size_t base;
    glm::vec3 t;
    if (!locate(p, base, t)) {
        gradient = glm::vec3(0.0f);
        return mBackground;
    }
    const std::size_t sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const glm::vec4 sample = detail::blendCell(mVoxels.get() + base, sy, sz, t, mVoxelSize);
    gradient = glm::vec3(sample.y, sample.z, sample.w);
    return sample.x;
}

}  // namespace ivis::render
