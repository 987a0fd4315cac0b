#include "method_options.h"

#include <ivis/core/errors.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/method_registry.h>

#include <cstdio>

namespace ivis::app {

void MethodOptions::addTo(CLI::App& command)
{
    std::string help = "Visualisation method:";
    for (const render::MethodInfo* info : render::methodRegistry()) help += "\n  " + info->name + ": " + info->help;
    mMethodOption = command.add_option("--method", method, help)->capture_default_str();
    for (const render::MethodInfo* info : render::methodRegistry())
        for (const render::ParameterSpec& spec : info->parameters) {
            CLI::Option*& option = mOptions[spec.key];
            std::string defaults;
            for (float v : spec.defaults) defaults += (defaults.empty() ? "" : " ") + CLI::detail::to_string(v);
            if (option) {  // a parameter several methods share: each method's own default where it differs
                const render::ParameterSpec& first = *render::methodInfo(mFirstMethod.at(spec.key)).parameter(spec.key);
                option->description(option->get_description() + "; " + info->name +
                                    (first.defaults == spec.defaults ? "" : " (default " + defaults + ")"));
                continue;
            }
            mFirstMethod[spec.key] = info->name;
            option = command.add_option(spec.option(), values[spec.key],
                                        spec.help + " (default " + defaults + ", " + CLI::detail::to_string(spec.lo) +
                                            " to " + CLI::detail::to_string(spec.hi) + "); for " + info->name);
            // Exactly as many values as the parameter has, so a mesh may follow the option.
            option->expected(int(spec.defaults.size()))->allow_extra_args(false);
        }
}

bool MethodOptions::givenParameter(const std::string& key) const
{
    const auto it = mOptions.find(key);
    return it != mOptions.end() && it->second->count() > 0;
}

bool MethodOptions::keeps(const render::Method& base) const
{
    return !(mMethodOption && mMethodOption->count() > 0) || method == base.name();
}

render::MethodPtr MethodOptions::create(const render::Method* base) const
{
    const bool kept = base && keeps(*base);
    const std::string name = kept ? base->name() : method;
    const render::MethodInfo& info = render::methodInfo(name);
    render::ParameterValues given = kept ? base->values() : render::ParameterValues{};
    for (const auto& [key, option] : mOptions) {
        if (option->count() == 0) continue;
        if (!info.parameter(key)) throw InputError(option->get_name() + " does not apply to the method " + name);
        given[key] = values.at(key);
    }
    return render::makeMethod(name, given);
}

void checkMethodFitsVolume(const render::Method& method, const vdb::VolumeOptions& volume)
{
    const render::ParameterValues values = method.values();
    for (const render::ParameterSpec& spec : method.info().parameters) {
        if (!spec.belowReach) continue;
        const float value = values.at(spec.key)[0];
        if (value < render::escapeDistance(float(volume.farFieldReach))) continue;
        char text[256];
        std::snprintf(text, sizeof text,
                      "%s %g is not below the volume's --reach %g (the curved rays escape at 0.999 of it): it would lie "
                      "outside the distance field (raise --reach above it)",
                      spec.option().c_str(), double(value), volume.farFieldReach);
        throw ValueError(text);
    }
}

}  // namespace ivis::app
