/// @file distance_field.h
/// @brief phi and grad phi of a SurfaceVolume anywhere between the surface and the hull: the fine
///        narrow band where a cell is fully inside it, the dense coarse far field elsewhere. Both
///        blend the exact distance and gradient stored per voxel (detail::blend): the gradient is
///        continuous everywhere, so that a curved ray's landing point is a smooth function of its
///        start (the gradient of a trilinear phi jumps at every voxel face).
/// @warning DistanceField is immutable and shared; create one Sampler per thread.
#pragma once

#include <ivis/render/dense_grid.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/vec3.hpp>

#include <algorithm>

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
    ///        far field (or, without one, its band) for fast sampling.
    explicit DistanceField(const vdb::SurfaceVolume& volume);

    /// @brief Per-thread sampler: owns the OpenVDB accessors, never shared between threads.
    class Sampler {
    public:
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
        openvdb::FloatGrid::ConstAccessor mPhi;
        openvdb::Vec3SGrid::ConstAccessor mGradient;
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
    /// @brief Voxel size of the grid that serves a sample whose value is @a phi (fine band or far field).
    float servingVoxelSize(float phi) const { return mHasFineBand && phi <= mFineUntil ? mVoxelSize : mFar.voxelSize(); }
    /// @brief Whether phi is an unsigned distance (open mesh).
    bool isUnsigned() const { return mVolume.unsignedDistance; }
    /// @brief The volume it samples.
    const vdb::SurfaceVolume& volume() const { return mVolume; }

private:
    const vdb::SurfaceVolume& mVolume;
    DenseGrid mFar;
    bool mHasFineBand;       ///< false when the dense copy is the fine grid itself
    float mVoxelSize;
    float mInvVoxelSize;
    float mOrigin;           ///< world coordinate of fine voxel centre 0 on each axis
    float mFineFrom;         ///< far values below this use the fine band alone
    float mFineUntil;        ///< far values above this never use it
    float mReach;
};

// Inline: curved rays sample at every step, mostly in the far field.

inline float DistanceField::Sampler::phi(const glm::vec3& p)
{
    glm::vec3 gradient;
    return phiAndGradient(p, gradient);
}

inline float DistanceField::Sampler::phiAndGradient(const glm::vec3& p, glm::vec3& gradient)
{
    const float far = mField.mFar.valueAndGradient(p, gradient);
    if (!mField.mHasFineBand || far > mField.mFineUntil) return far;
    return finePhiAndGradient(p, far, gradient);
}

}  // namespace ivis::render
