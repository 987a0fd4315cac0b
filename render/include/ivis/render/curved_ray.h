/// @file curved_ray.h
/// @brief InverseVis curved rays: seeds on the hull behind the object and particles falling onto
///        the hidden surface (METHOD.md, "InverseVis, I-").
#pragma once

#include <ivis/render/distance_field.h>

#include <glm/vec3.hpp>

namespace ivis::render {

/// @brief Parameters of the curved rays (paper defaults).
struct CurvedRayParams {
    float alpha = 0.5f;         ///< scale of the initial velocity
    float stepSize = 0.1f;      ///< symplectic Euler step h
    float hullOffset = 0.4f;    ///< phi0: the hull is {phi = phi0}
    float landingEpsilon = 0.0f;  ///< land when phi < eps; 0 = half a fine voxel
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
///        {phi = hullOffset}: sphere-traces backward from where the ray leaves the volume's box and
///        refines the crossing by bisection.
/// @return false when the ray never comes within hullOffset of the surface
bool findHullExit(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                  float hullOffset, glm::vec3& seed);

/// @brief v0 = alpha * g x (r x g) with g = grad phi / |grad phi| at the seed: alpha times the part
///        of the view direction r tangential to the hull.
glm::vec3 initialVelocity(const glm::vec3& gradient, const glm::vec3& viewDirection, float alpha);

/// @brief Integrates dp/dt = phi v/|v|, dv/dt = -grad phi with symplectic Euler:
///        v' = v - h grad phi(p); p' = p + h phi(p) v'/|v'|, until phi(p) < eps (landed), phi
///        reaches the field's reach (escaped) or maxSteps.
CurvedRayEnd traceCurvedRay(DistanceField::Sampler& sampler, const glm::vec3& seed, const glm::vec3& velocity,
                            const CurvedRayParams& params, float landingEpsilon);

/// @brief The landing threshold actually used: params.landingEpsilon or half a fine voxel.
float landingEpsilon(const CurvedRayParams& params, const DistanceField& field);

}  // namespace ivis::render
