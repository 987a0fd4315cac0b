/// @file inversevis_adaptive_method.h
/// @brief The `inversevis-adaptive` method (beyond the paper): InverseVis whose alpha varies
///        across the ring with where the pixel's view ray meets the hull.
#pragma once

#include <ivis/render/curved_ray_method.h>

#include <array>

namespace ivis::render {

/// @brief Alpha as a function of where a pixel lies across the ring:
///        alpha(c) = a0 + a1 c + a2 c^2, clamped to [0, kMaxAlpha], with c = r . grad phi / |grad phi|
///        at the hull seed (0 where the view ray grazes the hull, growing toward the silhouette).
struct AlphaProfile {
    /// a0, a1, a2; the default bends the rays near the silhouette furthest round the back.
    std::array<float, 3> coefficients{0.0f, 3.0f, 3.0f};
    int retries = 2;  ///< a ray that does not land is relaunched with half its alpha this often

    /// @brief alpha for the seed alignment @a c.
    float at(float c) const
    {
        const float alpha = coefficients[0] + c * (coefficients[1] + c * coefficients[2]);
        return alpha < 0.0f ? 0.0f : alpha > kMaxAlpha ? kMaxAlpha : alpha;
    }
};

/// @brief Description of `inversevis-adaptive`: alpha_profile (a0 a1 a2, optimised along the unit
///        gradient; tangent-linear gradient for the scalar energy), hull_offset, step, max_steps.
const MethodInfo& inverseVisAdaptiveMethodInfo();

/// @brief InverseVis with the alpha profile.
class InverseVisAdaptiveMethod final : public CurvedRayMethod {
public:
    /// @brief The method with rays @a ray and the alpha profile @a profile.
    InverseVisAdaptiveMethod(const CurvedRayParams& ray, const AlphaProfile& profile)
        : CurvedRayMethod(ray), mProfile(profile)
    {
    }
    const MethodInfo& info() const override { return inverseVisAdaptiveMethodInfo(); }
    ParameterValues values() const override;
    /// @brief The profile's alpha at the seed's alignment (halved on each relaunch) along its tangent.
    glm::vec3 launchVelocity(const CurvedRayStart& start, int launch) const override;
    /// @brief The profile's retries: a ray that does not land is launched again this often.
    int relaunches() const override { return mProfile.retries; }
    /// @brief The launch moves with the profile's coefficients; false where the profile is clamped.
    bool launchSensitivity(const CurvedRayStart& start, int launch, LaunchSensitivity& sensitivity) const override;
    /// @brief The alpha profile.
    const AlphaProfile& profile() const { return mProfile; }

private:
    AlphaProfile mProfile;
};

}  // namespace ivis::render
