/// @file curved_ray.h
/// @brief InverseVis curved rays: seeds on the hull behind the object and particles falling onto
///        the hidden surface (docs/method.md, "InverseVis, I-").
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/render/distance_field.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace ivis::render {

/// @brief Largest useful alpha: above about 4 the curved rays escape.
inline constexpr float kMaxAlpha = 4.0f;

/// @brief Parameters of the curved rays (paper defaults).
struct CurvedRayParams {
    float stepSize = 0.1f;      ///< symplectic Euler step h
    float hullOffset = 0.4f;    ///< phi0: the hull is {phi = phi0}
    float landingVoxels = 0.5f;  ///< land when phi < this many fine voxels (docs/method.md: about half a voxel)
    int maxSteps = 1000;        ///< rays still in flight after this many steps are misses
};

/// @brief Where a curved ray ended.
struct CurvedRayEnd {
    bool landed = false;
    glm::vec3 position{};  ///< last position (the landing point when landed)
    glm::vec3 velocity{};  ///< velocity at the last step
    int steps = 0;         ///< integration steps taken
};

/// @brief The FARTHEST intersection of the straight ray origin + t dir (t >= 0) with the hull
///        {phi = hullOffset}: sphere-traces backward from where the ray leaves @a hullBox and
///        refines the crossing by bisection.
/// @param hullBox a box containing the whole hull (e.g. hullBounds())
/// @return false when the ray never comes within hullOffset of the surface
bool findHullExit(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                  float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed);

/// @brief findHullExit() of each of @a count rays (unit @a directions) into @a seeds and @a found,
///        neighbouring rays (in groups of 8) first cleared together: a cone round the group's
///        central ray is sphere-traced backward by phi minus its radius, and each ray's own search
///        starts where the cone first comes within a voxel of the hull, or is skipped when the cone
///        cleared its whole interval (the view rays beside an object mostly miss the hull).
void findHullExits(DistanceField::Sampler& sampler, const glm::vec3* origins, const glm::vec3* directions,
                   std::size_t count, float hullOffset, const core::Bounds3& hullBox, glm::vec3* seeds, bool* found);

/// @brief How far above its lowest value (in fine voxels) phi may rise along a view ray within the
///        valley whose centre findClosestApproach takes. This and the constants below are the
///        viewer's shader's too (app/viewer/shaders.cpp writes them into it).
constexpr float kClosestApproachValley = 1.0f;
/// @brief The spacing (in fine voxels) of findClosestApproach's fine march and of its valley's samples.
constexpr float kClosestApproachSpacing = 0.25f;
/// @brief findClosestApproach's coarse march steps this many times kClosestApproachSpacing.
constexpr float kClosestApproachCoarseSteps = 16.0f;
/// @brief The golden-section search's ratio, (sqrt 5 - 1) / 2.
constexpr float kGoldenSectionRatio = 0.6180340f;

/// @brief The point of the straight ray origin + t dir (t >= 0) closest to the surface, where it
///        comes within @a hullOffset of it: phi sampled along the ray inside @a hullBox, skipping
///        by the 1-Lipschitz bound, refined by golden-section search, and centred in the valley of
///        the ray round that minimum where phi stays within kClosestApproachValley voxels of it
///        (the weighted mean of its samples kClosestApproachSpacing voxels apart, each weighted by
///        how far below that it lies), so that it moves continuously with the ray where phi barely rises.
/// @param bottom if given, the parameter t of the valley's bottom (the golden-section minimum)
/// @return false when the ray never comes within hullOffset of the surface, or when the valley's
///         centre does not (its least within about a voxel of hullOffset)
bool findClosestApproach(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                         float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed, float& distance,
                         float* bottom = nullptr);

/// @brief findClosestApproach with its coarse march replaced by a golden-section search within
///        @a reach of @a bottomHint (a neighbouring view ray's bottom, or one interpolated from
///        several): the phi found there bounds the fine march's least from the start, and the fine
///        march still visits the whole ray, so the valley is the ray's lowest as findClosestApproach
///        finds it. Without a phi below the hull near the hint, the coarse march runs after all.
bool findClosestApproachHinted(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                               float hullOffset, const core::Bounds3& hullBox, float bottomHint, float reach,
                               glm::vec3& seed, float& distance, float* bottom = nullptr);

/// @brief findClosestApproach with the valley's bottom sought only near @a bottomGuess (one
///        interpolated from neighbouring view rays' bottoms): golden-section search within @a reach
///        and two fine samples of it, no march along the whole ray to find where phi is least.
bool findClosestApproachNear(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                             float hullOffset, const core::Bounds3& hullBox, float bottomGuess, float reach,
                             glm::vec3& seed, float& distance, float* bottom = nullptr);

/// @brief A box around the hull {phi = hullOffset} of a mesh: its bounds @a meshBounds grown by the
///        offset plus one voxel, clipped to the volume's box.
core::Bounds3 hullBounds(const core::Bounds3& meshBounds, float hullOffset, float voxelSize);

/// @brief v0 = alpha * g x (r x g) with g = grad phi / |grad phi| at the seed: alpha times the part
///        of the view direction r tangential to the hull.
glm::vec3 initialVelocity(const glm::vec3& gradient, const glm::vec3& viewDirection, float alpha);

/// @brief What one integration step did.
enum class CurvedRayStep { Moved, Landed, Escaped };

/// @brief The move of one symplectic Euler step of dp/dt = phi v/|v|, dv/dt = -grad phi, given
///        @a phi and @a gradient at p: v' = v - h grad phi; p' = p + h phi v'/|v'|.
[[gnu::always_inline]] inline void moveCurvedRay(glm::vec3& p, glm::vec3& v, float phi, const glm::vec3& gradient,
                                                 float stepSize)
{
    v -= stepSize * gradient;
    const float speed = glm::length(v);
    const glm::vec3 heading = speed > 0.0f ? v / speed : -gradient;
    p += stepSize * phi * heading;
}

/// @brief One symplectic Euler step (moveCurvedRay) with phi and its gradient sampled at p; or,
///        without moving, Landed when phi(p) < eps and Escaped when phi(p) reaches @a escapeDistance.
/// @interface FieldSampler: float phiAndGradient(const glm::vec3& p, glm::vec3& gradient);
template <typename FieldSampler>
[[gnu::always_inline]] inline CurvedRayStep stepCurvedRay(FieldSampler& sampler, glm::vec3& p, glm::vec3& v,
                                                          float stepSize, float epsilon, float escapeDistance)
{
    glm::vec3 gradient;
    const float phi = sampler.phiAndGradient(p, gradient);
    if (phi < epsilon) return CurvedRayStep::Landed;
    if (phi >= escapeDistance) return CurvedRayStep::Escaped;
    moveCurvedRay(p, v, phi, gradient, stepSize);
    return CurvedRayStep::Moved;
}

/// @brief Integrates a curved ray with stepCurvedRay from @a seed until it lands, escapes or has
///        taken params.maxSteps steps.
template <typename FieldSampler>
CurvedRayEnd integrateCurvedRay(FieldSampler& sampler, const glm::vec3& seed, const glm::vec3& velocity,
                                const CurvedRayParams& params, float epsilon, float escapeDistance)
{
    CurvedRayEnd end;
    end.position = seed;
    end.velocity = velocity;
    for (; end.steps < params.maxSteps; ++end.steps) {
        const CurvedRayStep step =
            stepCurvedRay(sampler, end.position, end.velocity, params.stepSize, epsilon, escapeDistance);
        if (step == CurvedRayStep::Moved) continue;
        end.landed = step == CurvedRayStep::Landed;
        break;
    }
    return end;
}

/// @brief Where a curved ray counts as escaped: just below the distance field's @a reach (beyond
///        it phi is only a lower bound).
inline float escapeDistance(float reach) { return 0.999f * reach; }
/// @brief escapeDistance() of a volume's distance field.
inline float escapeDistance(const DistanceField& field) { return escapeDistance(field.reach()); }

/// @brief integrateCurvedRay on a volume's distance field, escaping at escapeDistance().
inline CurvedRayEnd traceCurvedRay(DistanceField::Sampler& sampler, const glm::vec3& seed, const glm::vec3& velocity,
                                   const CurvedRayParams& params, float epsilon)
{
    return integrateCurvedRay(sampler, seed, velocity, params, epsilon, escapeDistance(sampler.field()));
}

/// @brief The landing threshold in normalised units: params.landingVoxels fine voxels of @a field.
float landingEpsilon(const CurvedRayParams& params, const DistanceField& field);

}  // namespace ivis::render
