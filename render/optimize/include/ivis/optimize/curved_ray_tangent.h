/// @file curved_ray_tangent.h
/// @brief A curved ray integrated together with its tangent: the exact forward-mode derivative
///        of the discrete symplectic steps with respect to a parameter of the launch
///        (docs/method.md, "Optimising alpha").
#pragma once

#include <ivis/render/curved_ray.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace ivis::optimize {

using render::CurvedRayEnd;
using render::CurvedRayParams;

/// @brief A curved ray's end and the derivative of its end position with respect to a scalar
///        parameter of the initial conditions (forward mode, exact for the discrete steps).
struct CurvedRayTangent {
    CurvedRayEnd end;
    glm::vec3 dPosition{0.0f};  ///< d(end position) / d(parameter)
};

/// @brief integrateCurvedRay carrying the tangent (dp, dv) of one parameter through every step:
///        dv' = dv - h J dp;  dp' = dp + h (s . dp) u + h phi (I - u u^T) dv' / |v'|,
///        u = v'/|v'|, with J the Jacobian of the sampled gradient and s the slope of the sampled
///        phi. For alpha, dp0 = 0 and dv0 = v0/alpha.
/// @interface FieldSampler: float phiGradientJacobian(const glm::vec3&, glm::vec3&, glm::mat3&, glm::vec3&);
template <typename FieldSampler>
CurvedRayTangent integrateCurvedRayTangent(FieldSampler& sampler, const glm::vec3& seed, const glm::vec3& velocity,
                                           const glm::vec3& dVelocity, const CurvedRayParams& params,
                                           float epsilon, float escapeDistance)
{
    CurvedRayTangent result;
    glm::vec3 p = seed, v = velocity, dp(0.0f), dv = dVelocity, gradient, slope;
    glm::mat3 jacobian;
    const float h = params.stepSize;
    for (int step = 0; step < params.maxSteps; ++step) {
        const float phi = sampler.phiGradientJacobian(p, gradient, jacobian, slope);
        if (phi < epsilon) {
            result.end.landed = true;
            break;
        }
        if (phi >= escapeDistance) break;
        v -= h * gradient;
        dv -= h * (jacobian * dp);
        const float speed = glm::length(v);
        if (!(speed > 0.0f)) break;
        const glm::vec3 u = v / speed;
        const glm::vec3 du = (dv - glm::dot(u, dv) * u) / speed;
        dp += h * glm::dot(slope, dp) * u + h * phi * du;
        p += h * phi * u;
        ++result.end.steps;
    }
    result.end.position = p;
    result.end.velocity = v;
    result.dPosition = dp;
    return result;
}

}  // namespace ivis::optimize
