/// @file hessian.h
/// @brief The Hessian of the sampled distance, which the tangent-linear curved rays need.
#pragma once

#include <ivis/render/distance_field.h>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace ivis::optimize {

/// @brief A DistanceField::Sampler that also gives the Hessian of phi (the FieldSampler of
///        integrateCurvedRayTangent).
class HessianSampler {
public:
    /// @brief Reads @a sampler (which must outlive it).
    explicit HessianSampler(render::DistanceField::Sampler& sampler) : mSampler(sampler) {}
    /// @brief phi and gradient as DistanceField::Sampler::phiAndGradient, and the symmetric Hessian
    ///        by central differences of the gradient over one voxel of the grid that serves p. (The
    ///        trilinear gradient jumps across cell faces, so the in-cell Hessian would miss the
    ///        field's curvature.)
    float phiGradientHessian(const glm::vec3& p, glm::vec3& gradient, glm::mat3& hessian);

private:
    render::DistanceField::Sampler& mSampler;
};

}  // namespace ivis::optimize
