/// @file tangent_planes.h
/// @brief A curved ray's creep to its landing on checked tangent planes (docs/rendering.md,
///        "Tangent planes near the landing"): below a fine voxel of phi one sample of the field
///        serves the next steps as its tangent plane; where those steps end, the sample taken
///        there checks the plane, and a plane that fails is stepped again sample by sample.
#pragma once

#include <ivis/render/curved_ray.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace ivis::render {

/// @brief Steps a tangent plane serves after the step of its own sample.
constexpr int kTangentPlaneSteps = 16;
/// @brief Planes serve where phi is below this many fine voxels.
constexpr float kTangentPlaneVoxels = 1.0f;
/// @brief A plane's steps stand where phi sampled at their end lies within this many fine voxels
///        of the plane's phi there, and its gradient within kTangentPlaneGradientTolerance of the plane's.
constexpr float kTangentPlanePhiTolerance = 0.05f;
/// @brief See kTangentPlanePhiTolerance (the gradient's change, unit gradients).
constexpr float kTangentPlaneGradientTolerance = 0.1f;

/// @brief Where tangent planes serve and what their check allows, in normalised units.
struct TangentPlaneRule {
    float below = 0.0f;         ///< planes serve where phi < below (0: never; every step samples)
    float phiTolerance = 0.0f;  ///< the check's bound on phi (kTangentPlanePhiTolerance)
};

/// @brief The rule for a field whose fine voxels are @a voxelSize long.
inline TangentPlaneRule tangentPlaneRule(float voxelSize)
{
    return {kTangentPlaneVoxels * voxelSize, kTangentPlanePhiTolerance * voxelSize};
}

/// @brief One curved ray in flight: stepCurvedRay's steps, phi and its gradient taken from a
///        tangent plane where one serves. A plane starts at a sample below TangentPlaneRule::below
///        when the gradient's change over the last step, scaled to the plane's steps, stays within
///        half the check's tolerance (where the surface curves within a few voxels, as a thin
///        vessel's does, every step samples).
class CurvedRayFlight {
public:
    /// @brief A ray at the origin at rest (a placeholder to assign a flight to).
    CurvedRayFlight() = default;
    /// @brief A ray at @a seed with @a velocity, no step taken.
    CurvedRayFlight(const glm::vec3& seed, const glm::vec3& velocity)
    {
        mEnd.position = seed;
        mEnd.velocity = velocity;
    }

    /// @brief One step; false once the ray has landed or escaped (end().landed says which). A plane
    ///        that fails its check moves the ray back to the plane's sample (end().steps with it).
    ///        With @a kPlanes false every step samples (stepCurvedRay) and @a rule is not read.
    /// @interface FieldSampler: float phiAndGradient(const glm::vec3& p, glm::vec3& gradient);
    template <bool kPlanes, typename FieldSampler>
    [[gnu::always_inline]] inline bool advance(FieldSampler& sampler, const TangentPlaneRule& rule, float stepSize,
                                               float epsilon, float escapeDistance)
    {
        if constexpr (!kPlanes) {
            const CurvedRayStep step =
                stepCurvedRay(sampler, mEnd.position, mEnd.velocity, stepSize, epsilon, escapeDistance);
            if (step == CurvedRayStep::Moved) return ++mEnd.steps, true;
            mEnd.landed = step == CurvedRayStep::Landed;
            return false;
        } else {
            return advanceOnPlanes(sampler, rule, stepSize, epsilon, escapeDistance);
        }
    }

    /// @brief Where the ray is (its landing once advance() has returned false with end().landed).
    const CurvedRayEnd& end() const { return mEnd; }

private:
    /// advance() on tangent planes.
    template <typename FieldSampler>
    [[gnu::always_inline]] inline bool advanceOnPlanes(FieldSampler& sampler, const TangentPlaneRule& rule,
                                                       float stepSize, float epsilon, float escapeDistance)
    {
        glm::vec3 gradient;
        float phi = 0.0f;
        bool onPlane = false;
        if (mPlaneStepsLeft > 0) {
            phi = planePhi();
            onPlane = phi >= epsilon;  // a landing on the plane is sampled and checked first
            if (onPlane) --mPlaneStepsLeft, gradient = mPlane.gradient;
        }
        if (!onPlane) {
            phi = sampler.phiAndGradient(mEnd.position, gradient);
            if (mPlane.active && !standsCheck(phi, gradient, rule)) return true;
            if (phi < epsilon) {
                mEnd.landed = true;
                return false;
            }
            if (phi >= escapeDistance) return false;
            startPlaneIfSmooth(phi, gradient, rule, stepSize);
        }
        moveCurvedRay(mEnd.position, mEnd.velocity, phi, gradient, stepSize);
        ++mEnd.steps;
        return true;
    }

    struct Plane {
        bool active = false;  ///< a plane served the steps since its sample
        glm::vec3 origin{}, gradient{};
        float phi = 0.0f;
        glm::vec3 velocity{};  ///< the velocity at its sample
        int steps = 0;         ///< the steps taken before its sample
    };

    /// phi of the plane at the ray's position.
    float planePhi() const { return mPlane.phi + glm::dot(mPlane.gradient, mEnd.position - mPlane.origin); }

    /// Whether the plane's steps stand against the sample (@a phi, @a gradient) where they end;
    /// else the ray goes back to the plane's sample, to step from there sample by sample.
    bool standsCheck(float phi, const glm::vec3& gradient, const TangentPlaneRule& rule)
    {
        const float predicted = planePhi();
        mPlane.active = false;
        mPlaneStepsLeft = 0;
        if (std::abs(phi - predicted) <= rule.phiTolerance &&
            glm::length(gradient - mPlane.gradient) <= kTangentPlaneGradientTolerance)
            return true;
        mEnd.position = mPlane.origin, mEnd.velocity = mPlane.velocity, mEnd.steps = mPlane.steps;
        mSampledStepsLeft = kTangentPlaneSteps;
        mHasLastSample = false;
        return false;
    }

    /// Starts a plane at this sample where the rule allows it (see the class comment).
    void startPlaneIfSmooth(float phi, const glm::vec3& gradient, const TangentPlaneRule& rule, float stepSize)
    {
        if (!(phi < rule.below)) {
            mHasLastSample = false;
            return;
        }
        const bool hadLast = mHasLastSample;
        const glm::vec3 lastPosition = mLastPosition, lastGradient = mLastGradient;
        mLastPosition = mEnd.position, mLastGradient = gradient, mHasLastSample = true;
        if (mSampledStepsLeft > 0) {
            --mSampledStepsLeft;
            return;
        }
        // The plane's steps move the ray about kTangentPlaneSteps * stepSize * phi.
        const float reach = float(kTangentPlaneSteps) * stepSize * phi;
        if (!hadLast || !(glm::length(gradient - lastGradient) * reach <
                          0.5f * kTangentPlaneGradientTolerance * glm::length(mEnd.position - lastPosition)))
            return;
        mPlane = {true, mEnd.position, gradient, phi, mEnd.velocity, mEnd.steps};
        mPlaneStepsLeft = kTangentPlaneSteps;
    }

    CurvedRayEnd mEnd;
    Plane mPlane;
    int mPlaneStepsLeft = 0;    ///< steps the plane still serves
    int mSampledStepsLeft = 0;  ///< steps that sample, after a plane failed its check
    bool mHasLastSample = false;
    glm::vec3 mLastPosition{}, mLastGradient{};  ///< the last sample's point and gradient
};

}  // namespace ivis::render
