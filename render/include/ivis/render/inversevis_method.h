/// @file inversevis_method.h
/// @brief The `inversevis` method exactly as the paper: every curved ray starts with
///        v0 = alpha g x (r x g), one global alpha (docs/method.md, "InverseVis, I-").
#pragma once

#include <ivis/render/curved_ray_method.h>

namespace ivis::render {

/// @brief Description of `inversevis`: alpha (optimised; tangent-linear gradient for the scalar
///        energy; its range may be scanned), hull_offset, step, max_steps.
const MethodInfo& inverseVisMethodInfo();

/// @brief The paper's InverseVis with one alpha.
class InverseVisMethod final : public CurvedRayMethod {
public:
    /// @brief The method with rays @a ray and initial velocity scale @a alpha.
    InverseVisMethod(const CurvedRayParams& ray, float alpha) : CurvedRayMethod(ray), mAlpha(alpha) {}
    const MethodInfo& info() const override { return inverseVisMethodInfo(); }
    ParameterValues values() const override;
    /// @brief alpha along the seed's tangent (the paper's launch).
    glm::vec3 launchVelocity(const CurvedRayStart& start, int launch) const override;
    /// @brief The launch moves with alpha along the seed's tangent.
    bool launchSensitivity(const CurvedRayStart& start, int launch, LaunchSensitivity& sensitivity) const override;
    /// @brief The scale of the initial velocity.
    float alpha() const { return mAlpha; }

private:
    float mAlpha;
};

}  // namespace ivis::render
