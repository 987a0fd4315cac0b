/// @file hessian.h
/// @brief The derivatives of the sampled distance field that the tangent-linear curved rays need.
#pragma once

#include <ivis/render/distance_field.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace ivis::optimize {

/// @brief Central-difference step of HessianSampler, in voxels of the serving grid.
inline constexpr float kHessianStep = 0.05f;

/// @brief A DistanceField::Sampler that also gives the derivatives the tangent-linear curved rays
///        need (the FieldSampler of integrateCurvedRayTangent): the Jacobian of the sampled gradient
///        (the force) and the slope of the sampled phi (the step length), which differ from the
///        gradient by O(voxel / radius of curvature).
class HessianSampler {
public:
    /// @brief Reads @a sampler (which must outlive it).
    explicit HessianSampler(render::DistanceField::Sampler& sampler) : mSampler(sampler) {}
    /// @brief phi and gradient as DistanceField::Sampler::phiAndGradient; the Jacobian of the
    ///        gradient (column a = d gradient / d x_a; the blend of exact gradients is not a gradient
    ///        field, so it is not symmetric) and the slope of phi by central differences over
    ///        kHessianStep voxels of the grid that serves p: the sampled field is continuous and
    ///        smooth within a cell, so a short step gives the derivatives of what the rays feel.
    float phiGradientJacobian(const glm::vec3& p, glm::vec3& gradient, glm::mat3& jacobian, glm::vec3& slope);

private:
    render::DistanceField::Sampler& mSampler;
};

}  // namespace ivis::optimize
