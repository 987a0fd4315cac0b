// The method registry: every description is consistent, values are checked against it, and
// methods survive the round trips through JSON and the optimised-parameter vector, and each
// method's defaults fit the distance field's reach it asks for.
#include <ivis/core/errors.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/method_json.h>
#include <ivis/render/method_registry.h>

#include <gtest/gtest.h>

#include <set>

namespace ivis::render {
namespace {

TEST(MethodRegistry, NamesAndParameterKeysAreUniqueAndDefaultsWithinBounds)
{
    std::set<std::string> names;
    for (const MethodInfo* info : methodRegistry()) {
        EXPECT_TRUE(names.insert(info->name).second) << info->name;
        EXPECT_FALSE(info->help.empty()) << info->name;
        std::set<std::string> keys;
        for (const ParameterSpec& spec : info->parameters) {
            EXPECT_TRUE(keys.insert(spec.key).second) << info->name << " " << spec.key;
            EXPECT_LT(spec.lo, spec.hi) << spec.key;
            for (float v : spec.defaults) EXPECT_TRUE(v >= spec.lo && v <= spec.hi) << spec.key;
        }
        if (!info->scannedParameter.empty()) {
            const ParameterSpec* scanned = info->parameter(info->scannedParameter);
            ASSERT_NE(scanned, nullptr) << info->name;
            EXPECT_TRUE(scanned->optimised && scanned->defaults.size() == 1) << info->name;
        }
        const MethodPtr method = makeMethod(info->name);
        EXPECT_EQ(method->name(), info->name);
        EXPECT_EQ(method->values().size(), info->parameters.size()) << info->name;
        for (const ParameterSpec& spec : info->parameters) EXPECT_EQ(method->values().at(spec.key), spec.defaults);
        for (const std::string& key : info->viewValueKeys)  // the viewer reads both as uniforms, by key
            EXPECT_EQ(info->parameter(key), nullptr) << info->name << " " << key;
        // The analytic gradient is the curved rays' tangent-linear one, for the parameters they launch with.
        const bool launchesWithOptimised = method->curvedRays() && !optimisedParameters(*method).empty();
        EXPECT_EQ(launchesWithOptimised, info->tangentLinearGradient) << info->name;
    }
    EXPECT_EQ(methodNames().size(), names.size());
}

TEST(MethodRegistry, EveryMethodsDefaultsFitTheReachItAsksFor)
{
    EXPECT_EQ(makeMethod("front")->reachNeeded(), 0.0f) << "straight rays need no exterior distance";
    EXPECT_FLOAT_EQ(makeMethod("inversevis")->reachNeeded(), 1.0f) << "the paper's hull 0.4 and its rays' swing";
    EXPECT_FLOAT_EQ(makeMethod("inversevis-wrap")->reachNeeded(), 1.0f) << "its hull 0.6 and its rays' flight";
    EXPECT_FLOAT_EQ(makeMethod("inversevis-wrap", {{"hull_offset", {0.3f}}})->reachNeeded(), 0.7f);
    for (const MethodInfo* info : methodRegistry()) {
        const MethodPtr method = makeMethod(info->name);
        for (const ParameterSpec& spec : info->parameters)
            if (spec.belowReach) {
                EXPECT_LT(method->values().at(spec.key)[0], escapeDistance(method->reachNeeded())) << info->name;
            }
    }
}

TEST(MethodRegistry, ValuesAreCheckedAgainstTheDescription)
{
    EXPECT_THROW(makeMethod("ring"), InputError);
    EXPECT_THROW(makeMethod("mirror", {{"alpha", {0.5f}}}), InputError);
    EXPECT_THROW(makeMethod("inversevis", {{"alpha", {4.5f}}}), ValueError);
    EXPECT_THROW(makeMethod("inversevis", {{"alpha", {-0.1f}}}), ValueError);
    EXPECT_THROW(makeMethod("mirror", {{"mirror_w", {0.3f, 0.3f}}}), ValueError);
    EXPECT_THROW(makeMethod("inversevis", {{"max_steps", {10.5f}}}), ValueError);
    EXPECT_NO_THROW(makeMethod("inversevis", {{"alpha", {4.0f}}, {"hull_offset", {0.3f}}}));
}

TEST(MethodRegistry, EveryMethodSurvivesJson)
{
    for (const std::string& name : methodNames()) {
        ParameterValues changed = makeMethod(name)->values();
        for (auto& [key, values] : changed)
            for (float& v : values) v = v + 0.25f * (methodInfo(name).parameter(key)->integer ? 4.0f : 0.5f);
        const MethodPtr method = makeMethod(name, changed);
        const MethodPtr back = methodFromJson(nlohmann::json::parse(methodToJson(*method).dump()));
        EXPECT_EQ(back->name(), name);
        EXPECT_EQ(back->values(), method->values()) << name;
    }
    EXPECT_THROW(methodFromJson(nlohmann::json{{"alpha", 0.5}}), InputError);
    EXPECT_THROW(methodFromJson(nlohmann::json{{"method", "inversevis"}, {"alpha", "fast"}}), InputError);
}

TEST(MethodRegistry, OptimisedParametersRoundTripAndAreClampedToTheirBounds)
{
    const MethodPtr mirror = makeMethod("mirror", {{"mirror_distance_behind", {0.7f}}});
    const std::vector<double> x = optimisedParameters(*mirror);
    EXPECT_EQ(x, std::vector<double>({0.3f, 0.3f, 0.0, 0.0, 0.0}));
    const MethodPtr moved = withOptimisedParameters(*mirror, {0.1, 0.2, 0.3, 0.4, 99.0});
    EXPECT_EQ(moved->values().at("mirror_w"), std::vector<float>({0.1f, 0.2f, 0.3f, 0.4f, 10.0f}));
    EXPECT_EQ(moved->values().at("mirror_distance_behind"), std::vector<float>{0.7f}) << "fixed parameters stay";
    EXPECT_TRUE(sameFixedParameters(*mirror, *moved));
    EXPECT_FALSE(sameFixedParameters(*mirror, *makeMethod("mirror")));
    EXPECT_FALSE(sameFixedParameters(*makeMethod("inversevis"), *makeMethod("inversevis-adaptive")));
    EXPECT_EQ(optimisedParameters(*makeMethod("neugebauer")), std::vector<double>{});
    EXPECT_EQ(withOptimisedParameters(*makeMethod("inversevis"), {-1.0})->values().at("alpha"), std::vector<float>{0.0f});
}

}  // namespace
}  // namespace ivis::render
