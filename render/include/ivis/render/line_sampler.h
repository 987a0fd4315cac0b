/// @file line_sampler.h
/// @brief phi along one straight line, sampled many times a cell: the seed searches' marches,
///        golden sections and valleys (curved_ray.cpp) sample a view ray every quarter voxel, many
///        times in each cell of a far field several fine voxels wide.
#pragma once

#include <ivis/render/dense_grid.h>
#include <ivis/render/distance_field.h>

#include <glm/vec3.hpp>

#include <cstddef>

namespace ivis::render {

/// @brief DistanceField::Sampler::phi at the points origin + s direction of one line. Where a
///        separate far field (coarser than the fine band) alone serves phi, the second and later
///        samples in one far cell come from the quartic phi is along the line there (LineQuartic),
///        a few multiply-adds instead of a blend of eight corners; they differ from the sampler's
///        by rounding only.
class LineSampler {
public:
    /// @brief Samples phi along origin + s direction with @a sampler (which must outlive this).
    LineSampler(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction)
        : mSampler(sampler), mOrigin(origin), mDirection(direction), mFineUntil(sampler.field().fineUntil()),
          // Without a separate band the dense grid is the fine grid itself: a line crosses its cells
          // with a few samples each, which a quartic does not repay.
          mHalfFarCell(0.5f * sampler.field().farGrid().voxelSize()), mQuartics(sampler.field().hasFineBand())
    {
    }

    /// @brief phi at origin + s direction.
    [[gnu::always_inline]] float phi(float s)
    {
        if (!mQuartic.covers(s)) return mQuartics ? phiBeyondQuartic(s) : mSampler.phi(point(s));
        const float far = mQuartic.at(s);
        return far > mFineUntil ? far : mSampler.phi(point(s));  // below fineUntil the band serves
    }
    /// @brief phi() for a march whose last step was @a lastStep: after a step shorter than half a
    ///        far cell the next is likely in the same cell too, so a new cell's quartic is made at
    ///        once, at its first sample.
    [[gnu::always_inline]] float phiMarching(float s, float lastStep)
    {
        if (mQuartic.covers(s) || !mQuartics) return phi(s);
        return phiBeyondQuartic(s, lastStep < mHalfFarCell);
    }
    /// @brief Where a march that keeps only samples below @a best goes on after sampling @a s, at
    ///        @a next or beyond: the end of the far cell holding s when its quartic is at or above
    ///        best from s to there (bounded below: LineQuartic::lowerBound) and above fineUntil (so
    ///        that the quartic alone serves), else @a next.
    float skipAbove(float s, float next, float best) const
    {
        if (next >= mQuartic.hi || !mQuartic.covers(s)) return next;
        const float bound = mQuartic.lowerBound(s, mQuartic.hi);
        return bound >= best && bound > mFineUntil ? mQuartic.hi : next;
    }
    /// @brief The point of the line at parameter @a s.
    glm::vec3 point(float s) const { return mOrigin + s * mDirection; }
    /// @brief The sampler it reads (for samples off the line).
    DistanceField::Sampler& sampler() { return mSampler; }

private:
    /// phi at a parameter outside the quartic's cell, where quartics serve: the sampler's, or a new
    /// cell's quartic at the cell's second sample (at its first when @a eager).
    [[gnu::noinline]] float phiBeyondQuartic(float s, bool eager = false)
    {
        const glm::vec3 p = point(s);
        const DenseGrid& far = mSampler.field().farGrid();
        const std::ptrdiff_t cell = far.cellIndex(p);
        const bool again = cell == mLastCell;
        mLastCell = cell;
        // A cell's first sample (a march may cross it with one) is not worth its quartic.
        if (cell < 0 || !(again || eager) || !far.lineQuartic(mOrigin, mDirection, s, mQuartic))
            return mSampler.phi(p);
        const float value = mQuartic.at(s);
        return value > mFineUntil ? value : mSampler.phi(p);
    }

    DistanceField::Sampler& mSampler;
    glm::vec3 mOrigin, mDirection;
    float mFineUntil;                   ///< the field's fineUntil()
    LineQuartic mQuartic;               ///< the quartic of the far cell sampled last where one was made
    std::ptrdiff_t mLastCell = -1;      ///< the far cell of the last sample outside mQuartic's cell
    float mHalfFarCell;                 ///< half the far field's voxel size
    bool mQuartics;                     ///< whether the far cells are coarse enough for quartics
};

}  // namespace ivis::render
