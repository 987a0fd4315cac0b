/// @file curved_ray_gradient.h
/// @brief The analytic gradient of the scalar energy with respect to a curved-ray method's
///        optimised parameters (docs/method.md, "Optimising alpha"): per pixel, the tangent-linear
///        dP/d(launch) of its curved ray and the surface gradient of s at the landing point.
#pragma once

#include <ivis/optimize/energy.h>
#include <ivis/render/screen_map.h>

#include <vector>

namespace ivis::optimize {

/// @brief The landing of one curved-ray pixel and its sensitivity to the optimised parameters.
struct PixelLaunchDerivative {
    bool landed = false;             ///< false: direct pixel, missed hull, escaped, a cap, or a launch that does not move
    render::SurfacePoint point;      ///< where the curved ray lands
    glm::vec3 dPoint{0.0f};          ///< dP along the launch's sensitivity direction: the closest surface point's derivative
    double dImportance = 0.0;        ///< grad_S s . dPoint
    std::vector<double> perParameter;  ///< d(launch) / d(parameter k) along that direction
};

/// @brief The per-pixel term of curvedRayGradient at continuous pixel (x, y) of @a screen.
/// @pre screen's method traces curved rays
PixelLaunchDerivative pixelLaunchDerivative(const EnergyEvaluator& evaluator, const render::ScreenMap& screen,
                                            double x, double y, render::DistanceField::Sampler& sampler);

/// @brief Gradient of the scalar energy with respect to the optimised parameters of @a method
///        (optimisedParameters order): sum over I- of grad_S s(P) . dP/dparameter, times the pixel area.
/// @throw ValueError for the visibility kind (not differentiable: use forward differences) or a
///        method without a tangent-linear gradient
std::vector<double> curvedRayGradient(const EnergyEvaluator& evaluator, const core::Camera& camera,
                                      const render::MethodPtr& method);

}  // namespace ivis::optimize
