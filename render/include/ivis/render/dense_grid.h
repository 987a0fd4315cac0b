/// @file dense_grid.h
/// @brief A dense copy of a sparse distance grid's active region with the exact gradient stored per
///        voxel, sampled by detail::blend: a gradient continuous across voxel faces (so curved rays
///        bend smoothly) and a phi consistent with it.
#pragma once

#include <ivis/core/large_block.h>

#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ivis::render {

/// @brief Dense box of voxels (phi, exact gradient); outside the box every sample is the
///        background value with a zero gradient.
struct LineQuartic;

class DenseGrid {
public:
    DenseGrid() = default;
    /// @brief Copies the active bounding box (plus one voxel) of @a phi and @a gradient (same
    ///        topology); inactive voxels keep their (signed) background value and a zero gradient.
    DenseGrid(const openvdb::FloatGrid& phi, const openvdb::Vec3SGrid& gradient);

    /// @brief detail::blend's phi and gradient at world point p (background and a zero gradient
    ///        outside the box).
    float valueAndGradient(const glm::vec3& p, glm::vec3& gradient) const;
    /// @brief The quartic phi of the cell holding origin + s direction along that line (phi as
    ///        valueAndGradient gives it, up to rounding), into @a quartic; false outside the box.
    bool lineQuartic(const glm::vec3& origin, const glm::vec3& direction, float s, LineQuartic& quartic) const;
    /// @brief Index of the cell holding world point p (-1 outside the box): equal for two points
    ///        exactly when one lineQuartic serves both.
    std::ptrdiff_t cellIndex(const glm::vec3& p) const;
    /// @brief World-space voxel size.
    float voxelSize() const { return mVoxelSize; }

private:
    /// Cell origin index and fractional position of p; false when the cell is outside the box.
    bool locate(const glm::vec3& p, std::size_t& base, glm::vec3& t) const;

    core::LargeBlockArray<glm::vec4> mVoxels;  ///< (phi, gradient) per voxel, x fastest, then y, then z
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
///        blended gradient up to O(h^2), so that phi and the force the rays feel agree). The corners
///        are summed in pairs and the pairs in pairs, a chain of three additions instead of eight
///        (docs/decisions/simd-blend.md). With SSE2 the four components are summed in one register,
///        each by the same operations in the same order as without it, so that both give the same bits.
template <typename Corner>
[[gnu::always_inline]] inline glm::vec4 blendCorners(Corner corner, const glm::vec3& t, float voxelSize)
{
    float w[8];
    trilinearWeights(t, w);
#if defined(__SSE2__)
    __m128 part[4];
    for (int k = 0; k < 4; ++k)
        part[k] = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(w[2 * k]), _mm_loadu_ps(&corner(2 * k).x)),
                             _mm_mul_ps(_mm_set1_ps(w[2 * k + 1]), _mm_loadu_ps(&corner(2 * k + 1).x)));
    const __m128 total = _mm_add_ps(_mm_add_ps(part[0], part[1]), _mm_add_ps(part[2], part[3]));
    glm::vec4 sum;
    _mm_storeu_ps(&sum.x, total);
#else
    glm::vec4 part[4];
    for (int k = 0; k < 4; ++k) part[k] = w[2 * k] * corner(2 * k) + w[2 * k + 1] * corner(2 * k + 1);
    glm::vec4 sum = (part[0] + part[1]) + (part[2] + part[3]);
#endif
    // sum of w_i g_i . d_i, d_i the corner's offset in the cell
    const glm::vec4 &c1 = corner(1), &c2 = corner(2), &c3 = corner(3), &c4 = corner(4), &c5 = corner(5),
                    &c6 = corner(6), &c7 = corner(7);
    const float towardsCorner = ((w[1] * c1.y + w[2] * c2.z) + (w[3] * (c3.y + c3.z) + w[4] * c4.w)) +
                                ((w[5] * (c5.y + c5.w) + w[6] * (c6.z + c6.w)) + w[7] * ((c7.y + c7.z) + c7.w));
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

/// @brief blendCorners's phi along the line of cell fractions a + e s through a cell whose corners
///        are corner(i): the quartic sum_i w_i (phi_i + h g_i . (a + e s - d_i)) in s, its
///        coefficients of s^0 .. s^4 into @a c (the trilinear weights' three linear factors times
///        each corner's linear extrapolation, reduced along x, then y, then z).
template <typename Corner>
inline void blendQuartic(Corner corner, const glm::vec3& a, const glm::vec3& e, float voxelSize, float c[5])
{
    float base[8], slope[8];  // each corner's extrapolation along the line: base + slope s
    for (int i = 0; i < 8; ++i) {
        const glm::vec4& v = corner(i);
        const glm::vec3 g(v.y, v.z, v.w), d(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
        base[i] = v.x + voxelSize * (g.x * (a.x - d.x) + g.y * (a.y - d.y) + g.z * (a.z - d.z));
        slope[i] = voxelSize * (g.x * e.x + g.y * e.y + g.z * e.z);
    }
    float x[4][3];  // along x: lo + (a.x + e.x s)(hi - lo), one quadratic per (dy, dz)
    for (int j = 0; j < 4; ++j) {
        const float d0 = base[2 * j + 1] - base[2 * j], d1 = slope[2 * j + 1] - slope[2 * j];
        x[j][0] = base[2 * j] + a.x * d0;
        x[j][1] = slope[2 * j] + a.x * d1 + e.x * d0;
        x[j][2] = e.x * d1;
    }
    float y[2][4];  // along y: one cubic per dz
    for (int k = 0; k < 2; ++k) {
        const float* lo = x[2 * k];
        const float* hi = x[2 * k + 1];
        const float d0 = hi[0] - lo[0], d1 = hi[1] - lo[1], d2 = hi[2] - lo[2];
        y[k][0] = lo[0] + a.y * d0;
        y[k][1] = lo[1] + a.y * d1 + e.y * d0;
        y[k][2] = lo[2] + a.y * d2 + e.y * d1;
        y[k][3] = e.y * d2;
    }
    float d[4];  // along z: the quartic
    for (int m = 0; m < 4; ++m) d[m] = y[1][m] - y[0][m];
    c[0] = y[0][0] + a.z * d[0];
    for (int m = 1; m < 4; ++m) c[m] = y[0][m] + a.z * d[m] + e.z * d[m - 1];
    c[4] = e.z * d[3];
}
}  // namespace detail

/// @brief phi along the straight line origin + s direction where it crosses one cell of a
///        DenseGrid: the quartic that detail::blend's phi is there (DenseGrid::lineQuartic).
struct LineQuartic {
    float lo = 1.0f, hi = 0.0f;  ///< the parameters s of the line within the cell (empty: lo > hi)
    float s0 = 0.0f;             ///< the quartic's variable is s - s0
    float c[5] = {};             ///< its coefficients of (s - s0)^0 .. ^4

    /// @brief Whether parameter @a s lies within the cell.
    bool covers(float s) const { return s >= lo && s <= hi; }
    /// @brief phi at parameter @a s (within the cell).
    float at(float s) const
    {
        const float u = s - s0;
        return (((c[4] * u + c[3]) * u + c[2]) * u + c[1]) * u + c[0];
    }
    /// @brief A lower bound of the quartic on the parameters [@a from, @a to]: the least of its
    ///        Bernstein coefficients there (the quartic lies within their convex hull).
    float lowerBound(float from, float to) const
    {
        // Taylor coefficients at from (Horner's shifts), then scaled to the interval's length.
        const float u = from - s0, length = to - from;
        float d[5] = {c[0], c[1], c[2], c[3], c[4]};
        for (int k = 0; k < 4; ++k)
            for (int j = 3; j >= k; --j) d[j] += u * d[j + 1];
        float scale = length;
        for (int k = 1; k <= 4; ++k, scale *= length) d[k] *= scale;
        const float b1 = d[0] + 0.25f * d[1];
        const float b2 = d[0] + 0.5f * d[1] + d[2] * (1.0f / 6.0f);
        const float b3 = d[0] + 0.75f * d[1] + 0.5f * d[2] + 0.25f * d[3];
        const float b4 = d[0] + d[1] + d[2] + d[3] + d[4];
        return std::min(std::min(std::min(d[0], b1), std::min(b2, b3)), b4);
    }
};

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

inline std::ptrdiff_t DenseGrid::cellIndex(const glm::vec3& p) const
{
    std::size_t base;
    glm::vec3 t;
    return locate(p, base, t) ? std::ptrdiff_t(base) : -1;
}

inline bool DenseGrid::lineQuartic(const glm::vec3& origin, const glm::vec3& direction, float s,
                                   LineQuartic& quartic) const
{
    std::size_t base;
    glm::vec3 a;
    if (!locate(origin + s * direction, base, a)) return false;
    const glm::vec3 e = direction * mInvVoxelSize;  // the fractions' change per unit of s
    float lo = -std::numeric_limits<float>::infinity(), hi = std::numeric_limits<float>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (e[k] == 0.0f) continue;
        const float enter = -a[k] / e[k], leave = (1.0f - a[k]) / e[k];
        lo = std::max(lo, std::min(enter, leave));
        hi = std::min(hi, std::max(enter, leave));
    }
    quartic.lo = s + lo;
    quartic.hi = s + hi;
    quartic.s0 = s;
    const std::size_t sy = std::size_t(mDims[0]), sz = sy * mDims[1];
    const glm::vec4* v = mVoxels.get() + base;
    detail::blendQuartic([v, sy, sz](int i) -> const glm::vec4& { return v[(i & 1) + (i & 2 ? sy : 0) + (i & 4 ? sz : 0)]; },
                         a, e, mVoxelSize, quartic.c);
    return true;
}

}  // namespace ivis::render
