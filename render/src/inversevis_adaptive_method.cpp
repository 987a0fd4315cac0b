#include <ivis/render/inversevis_adaptive_method.h>

namespace ivis::render {
namespace {

/// alpha of launch @a launch: the profile's alpha halved per relaunch.
float launchAlpha(const AlphaProfile& profile, const CurvedRayStart& start, int launch)
{
    float alpha = profile.at(start.alignment);
    for (int k = 0; k < launch; ++k) alpha *= 0.5f;
    return alpha;
}

}  // namespace

ParameterValues InverseVisAdaptiveMethod::values() const
{
    ParameterValues values = curvedRayValues(rayParams());
    values["alpha_profile"] = {mProfile.coefficients.begin(), mProfile.coefficients.end()};
    return values;
}

glm::vec3 InverseVisAdaptiveMethod::launchVelocity(const CurvedRayStart& start, int launch) const
{
    return launchAlpha(mProfile, start, launch) * start.tangent;
}

bool InverseVisAdaptiveMethod::launchSensitivity(const CurvedRayStart& start, int launch,
                                                 LaunchSensitivity& sensitivity) const
{
    // alpha = a0 + a1 c + a2 c^2 moves with a_k by c^k, unless the profile is clamped there.
    const float alpha = mProfile.at(start.alignment);
    if (alpha <= 0.0f || alpha >= kMaxAlpha) return false;
    const double relaunchScale = double(launchAlpha(mProfile, start, launch) / alpha);
    sensitivity.direction = start.tangent;
    sensitivity.perParameter.assign(mProfile.coefficients.size(), 0.0);
    double power = 1.0;
    for (double& d : sensitivity.perParameter) {
        d = relaunchScale * power;
        power *= start.alignment;
    }
    return true;
}

const MethodInfo& inverseVisAdaptiveMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "inversevis-adaptive";
        i.help = "InverseVis with alpha varying across the ring (beyond the paper)";
        const AlphaProfile defaults;
        i.parameters = {ParameterSpec{"alpha_profile", "alpha(c) = a0 + a1 c + a2 c^2 across the ring",
                                      {defaults.coefficients.begin(), defaults.coefficients.end()}, -16.0f, 16.0f}
                            .movedByTheAscent()};
        for (const ParameterSpec& spec : curvedRaySpecs()) i.parameters.push_back(spec);
        i.tangentLinearGradient = true;
        // Its visibility gradient is far smaller than the profile's useful steps.
        i.lineSearch = LineSearch{true, 1.0, 0.1};
        i.create = [](const ParameterValues& v) {
            AlphaProfile profile;
            for (std::size_t k = 0; k < profile.coefficients.size(); ++k) profile.coefficients[k] = v.at("alpha_profile")[k];
            return std::make_shared<const InverseVisAdaptiveMethod>(curvedRayParamsFrom(v), profile);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
