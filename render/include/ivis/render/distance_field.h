/// @file distance_field.h
/// @brief phi and grad phi of a SurfaceVolume anywhere between the surface and the hull: the fine
///        narrow band where a cell is fully inside it, the dense coarse far field elsewhere. Both
///        blend the exact distance and gradient stored per voxel (detail::blend): the gradient is
///        continuous everywhere, so that a curved ray's landing point is a smooth function of its
///        start (the gradient of a trilinear phi jumps at every voxel face).
/// @warning DistanceField is immutable and shared; create one Sampler per thread.
#pragma once

#include <ivis/render/band_bricks.h>
#include <ivis/render/dense_grid.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::render {

namespace detail {
/// @brief Weight of the fine band at far value @a far: 1 up to @a from, 0 from @a until on, a
///        smoothstep between (so phi and its gradient pass from band to far field continuously).
inline float fineWeight(float far, float from, float until)
{
    const float t = std::clamp((until - far) / (until - from), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
}  // namespace detail

/// @brief Read-only distance field of one volume.
class DistanceField {
public:
    /// @brief Wraps @a volume (kept by reference: it must outlive this object) and densifies its
    ///        far field (or, without one, its band) and bricks its band for fast sampling.
    explicit DistanceField(const vdb::SurfaceVolume& volume);

    /// @brief Per-thread sampler: owns its brick cache and an OpenVDB accessor, never shared between threads.
    class Sampler {
    public:
        /// @brief A sampler of @a field (which must outlive it), its brick cache empty.
        explicit Sampler(const DistanceField& field);
        /// @brief phi at p (world = normalised units), as phiAndGradient.
        float phi(const glm::vec3& p);
        /// @brief phi and gradient at p: detail::blend of the corners of its cell.
        float phiAndGradient(const glm::vec3& p, glm::vec3& gradient);
        /// @brief Closest triangle stored at the fine voxel nearest to p (-1 outside the band).
        int nearestTriangle(const glm::vec3& p);
        /// @brief The field this sampler reads.
        const DistanceField& field() const { return mField; }

    private:
        /// detail::blend's (phi, gradient) of the fine cell containing p, false unless all 8
        /// corners are active.
        bool fineSample(const glm::vec3& p, glm::vec4& sample);
        /// phi and gradient from the fine band at p where its cell is complete, else @a far (and
        /// the far gradient already in @a gradient).
        float finePhiAndGradient(const glm::vec3& p, float far, glm::vec3& gradient);

        const DistanceField& mField;
        glm::ivec3 mLeaf{-1};                 ///< leaf (fine index / 8) of the last brick looked up
        const glm::vec4* mBrick = nullptr;    ///< its brick (nullptr: no band there)
        openvdb::Int32Grid::ConstAccessor mTriangle;
    };

    /// @brief A new sampler for the calling thread.
    Sampler sampler() const { return Sampler(*this); }
    /// @brief Fine voxel size (normalised units).
    float voxelSize() const { return mVoxelSize; }
    /// @brief Exterior distance up to which phi is exact; beyond it phi is clamped to this value.
    float reach() const { return mReach; }
    /// @brief Far-field values below this use the fine band alone (where its cell is complete).
    float fineFrom() const { return mFineFrom; }
    /// @brief Far-field values above this never use the fine band; between fineFrom() and this the
    ///        two are blended (detail::fineWeight).
    float fineUntil() const { return mFineUntil; }
    /// @brief The dense grid every sample reads first: the far field, or the fine grid itself
    ///        when the volume has no separate far field.
    const DenseGrid& farGrid() const { return mFar; }
    /// @brief Whether the fine band is separate from farGrid() (and serves below fineUntil()).
    bool hasFineBand() const { return mHasFineBand; }
    /// @brief Voxel size of the grid that serves a sample whose value is @a phi (fine band or far field).
    float servingVoxelSize(float phi) const { return mHasFineBand && phi <= mFineUntil ? mVoxelSize : mFar.voxelSize(); }
    /// @brief Whether phi is an unsigned distance (open mesh).
    bool isUnsigned() const { return mVolume.unsignedDistance; }
    /// @brief The volume it samples.
    const vdb::SurfaceVolume& volume() const { return mVolume; }

private:
    const vdb::SurfaceVolume& mVolume;
    DenseGrid mFar;
    BandBricks mBand;        ///< the fine band, when the far field is separate
    bool mHasFineBand;       ///< false when the dense copy is the fine grid itself
    float mVoxelSize;
    float mInvVoxelSize;
    float mOrigin;           ///< world coordinate of fine voxel centre 0 on each axis
    float mFineFrom;         ///< far values below this use the fine band alone
    float mFineUntil;        ///< far values above this never use it
    float mReach;
};

// Inline: curved rays and shadow rays sample at every step.

[[gnu::always_inline]] inline float DistanceField::Sampler::phi(const glm::vec3& p)
{
    glm::vec3 gradient;
    return phiAndGradient(p, gradient);
}

[[gnu::always_inline]] inline float DistanceField::Sampler::phiAndGradient(const glm::vec3& p, glm::vec3& gradient)
{
    const float far = mField.mFar.valueAndGradient(p, gradient);
    if (!mField.mHasFineBand || far > mField.mFineUntil) return far;
    return finePhiAndGradient(p, far, gradient);
}

inline bool DistanceField::Sampler::fineSample(const glm::vec3& p, glm::vec4& sample)
{
    const glm::vec3 q = (p - glm::vec3(mField.mOrigin)) * mField.mInvVoxelSize;
    if (!(q.x >= 0.0f && q.y >= 0.0f && q.z >= 0.0f)) return false;  // outside the box: no band there
    const int x = int(q.x), y = int(q.y), z = int(q.z);                // truncation = floor for q >= 0
    const glm::ivec3 leaf(x >> 3, y >> 3, z >> 3);
    if (leaf != mLeaf) {
        mLeaf = leaf;
        mBrick = mField.mBand.find(x, y, z);
    }
    if (!mBrick) return false;
    constexpr int sy = BandBricks::kEdge, sz = sy * sy;
    sample = detail::blendCell(mBrick + BandBricks::voxelOffset(x & 7, y & 7, z & 7), sy, sz,
                               q - glm::vec3(float(x), float(y), float(z)), mField.mVoxelSize);
    return !std::isnan(sample.x);  // NaN: some corner is outside the band
}

inline float DistanceField::Sampler::finePhiAndGradient(const glm::vec3& p, float far, glm::vec3& gradient)
{
    glm::vec4 sample;
    if (!fineSample(p, sample)) return far;
    const float w = detail::fineWeight(far, mField.mFineFrom, mField.mFineUntil);
    gradient = w * glm::vec3(sample.y, sample.z, sample.w) + (1.0f - w) * gradient;
    return w * sample.x + (1.0f - w) * far;
}

}  // namespace ivis::render
