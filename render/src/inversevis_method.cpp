#include <ivis/render/inversevis_method.h>

namespace ivis::render {

ParameterValues InverseVisMethod::values() const
{
    ParameterValues values = curvedRayValues(rayParams());
    values["alpha"] = {mAlpha};
    return values;
}

glm::vec3 InverseVisMethod::launchVelocity(const CurvedRayStart& start, int /*launch*/) const
{
    return mAlpha * start.tangent;
}

bool InverseVisMethod::launchSensitivity(const CurvedRayStart& start, int /*launch*/,
                                         LaunchSensitivity& sensitivity) const
{
    sensitivity.direction = start.tangent;
    sensitivity.perParameter = {1.0};
    return true;
}

const MethodInfo& inverseVisMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "inversevis";
        i.help = "curved rays from the hull onto the hidden surface (the paper's model)";
        i.parameters = {ParameterSpec{"alpha", "initial velocity scale (above ~4 the rays escape)", {0.5f}, 0.0f, kMaxAlpha}
                            .movedByTheAscent()};
        for (const ParameterSpec& spec : curvedRaySpecs()) i.parameters.push_back(spec);
        i.tangentLinearGradient = true;
        i.scannedParameter = "alpha";
        i.create = [](const ParameterValues& v) {
            return std::make_shared<const InverseVisMethod>(curvedRayParamsFrom(v), v.at("alpha")[0]);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
