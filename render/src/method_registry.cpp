#include <ivis/render/method_registry.h>

#include <ivis/core/errors.h>
#include <ivis/core/number_text.h>
#include <ivis/render/backfaces_method.h>
#include <ivis/render/front_method.h>
#include <ivis/render/inversevis_adaptive_method.h>
#include <ivis/render/inversevis_method.h>
#include <ivis/render/inversevis_wrap_method.h>
#include <ivis/render/mirror_method.h>
#include <ivis/render/neugebauer_method.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ivis::render {
namespace {

using core::shortNumber;

/// Checks one parameter's values against its description.
void validate(const MethodInfo& info, const ParameterSpec& spec, const std::vector<float>& values)
{
    const std::string what = info.name + " " + spec.option();
    if (values.size() != spec.defaults.size())
        throw ValueError(what + " takes " + std::to_string(spec.defaults.size()) + " value(s), not " +
                         std::to_string(values.size()));
    for (float v : values) {
        if (!(v >= spec.lo && v <= spec.hi))
            throw ValueError(what + " " + shortNumber(v) + " is out of range (" + shortNumber(spec.lo) + " to " +
                             shortNumber(spec.hi) + ")");
        if (spec.integer && v != std::round(v)) throw ValueError(what + " " + shortNumber(v) + " is not a whole number");
    }
}

}  // namespace

const std::vector<const MethodInfo*>& methodRegistry()
{
    // One line per method: adding a method is its file pair and a line here.
    static const std::vector<const MethodInfo*> registry = {
        &frontMethodInfo(),  &backfacesMethodInfo(),  &neugebauerMethodInfo(),
        &mirrorMethodInfo(), &inverseVisMethodInfo(), &inverseVisAdaptiveMethodInfo(), &inverseVisWrapMethodInfo()};
    return registry;
}

MethodPtr defaultMethod() { return makeMethod(inverseVisWrapMethodInfo().name); }

std::vector<std::string> methodNames()
{
    std::vector<std::string> names;
    for (const MethodInfo* info : methodRegistry()) names.push_back(info->name);
    return names;
}

const MethodInfo& methodInfo(const std::string& name)
{
    for (const MethodInfo* info : methodRegistry())
        if (info->name == name) return *info;
    std::string known;
    for (const auto& n : methodNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("unknown method '" + name + "' (known: " + known + ")");
}

MethodPtr makeMethod(const std::string& name, const ParameterValues& values)
{
    const MethodInfo& info = methodInfo(name);
    for (const auto& [key, value] : values)
        if (!info.parameter(key)) throw InputError("method " + name + " has no parameter '" + key + "'");
    ParameterValues complete;
    for (const ParameterSpec& spec : info.parameters) {
        const auto given = values.find(spec.key);
        complete[spec.key] = given != values.end() ? given->second : spec.defaults;
        validate(info, spec, complete[spec.key]);
    }
    return info.create(complete);
}

MethodPtr withValues(const Method& method, const ParameterValues& changes)
{
    ParameterValues values = method.values();
    for (const auto& [key, value] : changes) values[key] = value;
    return makeMethod(method.name(), values);
}

std::vector<double> optimisedParameters(const Method& method)
{
    const ParameterValues values = method.values();
    std::vector<double> x;
    for (const ParameterSpec& spec : method.info().parameters)
        if (spec.optimised) x.insert(x.end(), values.at(spec.key).begin(), values.at(spec.key).end());
    return x;
}

MethodPtr withOptimisedParameters(const Method& method, const std::vector<double>& x)
{
    ParameterValues values = method.values();
    std::size_t next = 0;
    for (const ParameterSpec& spec : method.info().parameters) {
        if (!spec.optimised) continue;
        for (float& v : values[spec.key]) v = float(std::clamp(x.at(next++), double(spec.lo), double(spec.hi)));
    }
    IVIS_CHECK(next == x.size());
    return method.info().create(values);
}

bool sameFixedParameters(const Method& a, const Method& b)
{
    if (&a.info() != &b.info()) return false;
    const ParameterValues va = a.values(), vb = b.values();
    for (const ParameterSpec& spec : a.info().parameters)
        if (!spec.optimised && va.at(spec.key) != vb.at(spec.key)) return false;
    return true;
}

std::string describeOptimisedParameters(const Method& method)
{
    const ParameterValues values = method.values();
    std::string text;
    for (const ParameterSpec& spec : method.info().parameters) {
        if (!spec.optimised) continue;
        text += (text.empty() ? "" : ", ") + spec.key;
        for (float v : values.at(spec.key)) {
            char number[32];
            std::snprintf(number, sizeof number, " %.3f", double(v));
            text += number;
        }
    }
    return text;
}

double reachNeededBy(const std::vector<MethodPtr>& methods, double atLeast)
{
    double reach = atLeast;
    for (const MethodPtr& method : methods) reach = std::max(reach, std::round(double(method->reachNeeded()) * 1e4) / 1e4);
    return reach;
}

}  // namespace ivis::render
