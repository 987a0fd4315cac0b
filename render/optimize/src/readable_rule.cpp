#include <ivis/optimize/readable_rule.h>

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/method_registry.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace ivis::optimize {
namespace {

/// The ladder's rungs run from an eighth of the method's own value to eight times it, each
/// sqrt(2) times the one before: 13 rungs, the own value the middle one.
constexpr int kRungsEachSide = 6;
/// Sampled rows and columns across the picture (about 3 * 200^2 pixels at any resolution).
constexpr int kSampledLines = 200;
/// A picture wider than this many heights is judged on its middle part.
constexpr int kMaxAspect = 4;

}  // namespace

double coherenceLowerBound(const Coherence& coherence)
{
    const double value = coherence.value();
    if (coherence.pairs == 0) return value;
    return value - 2.0 * std::sqrt(value * (1.0 - value) / double(coherence.pairs));
}

std::vector<Coherence> coherenceAtSettings(const render::RenderScene& scene, const core::Camera& camera,
                                           const render::Method& method, const glm::ivec2& size, int stride,
                                           const std::vector<float>& values)
{
    const std::string& parameter = method.info().readableRuleParameter;
    if (parameter.empty() || !method.curved()) throw ValueError(method.name() + " has no readable rule's parameter");
    if (values.empty() || size.x < 1 || size.y < 1 || stride < 1)
        throw ValueError("coherence at settings needs values, a positive size and a positive stride");
    const float loosest = *std::max_element(values.begin(), values.end());
    const render::MethodPtr traced = render::withValues(method, {{parameter, {loosest}}});
    const core::CameraFrame frame(camera, size.x, size.y);
    const render::CurvedRayMap rays(scene, frame, *traced->curved());

    // The sampled pixels' landings and bends (infinite where no curved ray lands): in a sampled
    // row the sampled columns and their right neighbours, in the row below one the sampled columns.
    const std::size_t pixels = std::size_t(size.x) * size.y;
    std::vector<glm::vec3> points(pixels);
    std::vector<float> bends(pixels, std::numeric_limits<float>::infinity());
    tbb::parallel_for(0, size.y, [&](int y) {
        if (core::interruptRequested()) return;  // Ctrl-C: the rest is not needed (thrown below)
        render::DistanceField::Sampler sampler = scene.distance().sampler();
        std::vector<render::CurvedRayStart> aimed;
        std::vector<std::size_t> aimedAt;
        for (int x = 0; x < size.x; ++x) {
            const bool sampled = y % stride == 0 ? x % stride == 0 || (x - 1) % stride == 0
                                                 : (y - 1) % stride == 0 && x % stride == 0;
            render::CurvedRayStart start;
            if (!sampled || rays.hitsSurface(x + 0.5, y + 0.5) || !rays.aimedStart(x + 0.5, y + 0.5, sampler, start))
                continue;
            aimed.push_back(start);
            aimedAt.push_back(std::size_t(y) * size.x + x);
        }
        // The stability rule on the row's rays together (their probes traced in lanes).
        std::vector<render::CurvedRayStart*> judged(aimed.size());
        for (std::size_t k = 0; k < aimed.size(); ++k) judged[k] = &aimed[k];
        std::unique_ptr<bool[]> stable(new bool[aimed.size()]);
        rays.areStable(judged.data(), judged.size(), sampler, stable.get());
        std::vector<render::CurvedRayStart> starts;
        std::vector<std::size_t> at;
        for (std::size_t k = 0; k < aimed.size(); ++k)
            if (stable[k]) starts.push_back(aimed[k]), at.push_back(aimedAt[k]);
        std::vector<render::PixelMapping> landings(starts.size());
        rays.landingMany(starts.data(), starts.size(), sampler, landings.data());
        for (std::size_t k = 0; k < starts.size(); ++k) {
            if (landings[k].region != render::Region::Indirect) continue;
            points[at[k]] = landings[k].point.position;
            bends[at[k]] = starts[k].bend;
        }
    });
    if (core::interruptRequested()) throw Cancelled("readable rule cancelled");
    std::vector<Coherence> result;
    std::vector<char> drawn(pixels);
    for (const float value : values) {
        for (std::size_t i = 0; i < pixels; ++i) drawn[i] = bends[i] <= value;
        result.push_back(mappingCoherence(drawn, points, size.x, size.y, kCoherenceDistance, nullptr, stride));
    }
    return result;
}

glm::ivec2 readableRulePictureSize(int width, int height)
{
    if (width < 1 || height < 1) throw ValueError("the readable rule needs a picture of positive size");
    const double columns = std::round(double(kCoherenceResolution) * width / height);
    return {int(std::clamp(columns, 1.0, double(kMaxAspect * kCoherenceResolution))), kCoherenceResolution};
}

std::vector<float> readableRuleLadder(const render::Method& method)
{
    const std::string& parameter = method.info().readableRuleParameter;
    if (parameter.empty()) return {};
    const render::ParameterSpec& spec = *method.info().parameter(parameter);
    const float own = method.values().at(parameter).at(0);
    std::vector<float> ladder;
    for (int k = -kRungsEachSide; k <= kRungsEachSide; ++k) {
        const float value = k == 0 ? own : std::clamp(own * std::exp2(0.5f * float(k)), spec.lo, spec.hi);
        if (ladder.empty() || value > ladder.back()) ladder.push_back(value);
    }
    return ladder;
}

ReadableSetting loosestReadable(const render::RenderScene& scene, const core::Camera& camera,
                                const render::MethodPtr& method, const glm::ivec2& size, double minCoherence,
                                const std::function<bool(const render::MethodPtr&)>& keeps)
{
    if (size.x < 1 || size.y < 1) throw ValueError("the readable rule needs a positive size");
    if (!(minCoherence > 0.0 && minCoherence <= 1.0)) throw ValueError("the minimum coherence must lie in (0, 1]");
    const std::string& parameter = method->info().readableRuleParameter;
    if (parameter.empty()) return {method, {}, size};
    const std::vector<float> ladder = readableRuleLadder(*method);
    const std::vector<Coherence> coherence =
        coherenceAtSettings(scene, camera, *method, size, std::max(1, size.y / kSampledLines), ladder);
    std::size_t chosen = 0;
    while (chosen + 1 < ladder.size() && coherenceLowerBound(coherence[chosen + 1]) >= minCoherence) ++chosen;
    const float own = method->values().at(parameter).at(0);
    const auto atRung = [&](std::size_t k) {
        return ladder[k] == own ? method : render::withValues(*method, {{parameter, {ladder[k]}}});
    };
    if (keeps && ladder[chosen] > own && !keeps(atRung(chosen))) {
        // The loosest rung between the own one (taken to keep) and the chosen one that keeps, by
        // bisection: each rung draws every ray a tighter one draws, so once a rung splits what
        // `keeps` asks for, looser ones are taken to split it too.
        std::size_t keeping = std::size_t(std::find(ladder.begin(), ladder.end(), own) - ladder.begin());
        std::size_t splitting = chosen;
        IVIS_CHECK(keeping < splitting);
        while (splitting - keeping > 1) {
            const std::size_t middle = (keeping + splitting) / 2;
            (keeps(atRung(middle)) ? keeping : splitting) = middle;
        }
        chosen = keeping;
    }
    const bool keepsMinimum = coherenceLowerBound(coherence[chosen]) >= minCoherence;
    return {atRung(chosen), coherence[chosen], size, keepsMinimum};
}

nlohmann::json readableSettingJson(const optimize::ReadableSetting& setting)
{
    const std::string& parameter = setting.method->info().readableRuleParameter;
    return {{"parameter", parameter},
            {"value", setting.method->values().at(parameter).at(0)},
            {"estimated_coherence", setting.coherence.value()},
            {"sampled_pairs", setting.coherence.pairs},
            {"picture_size", {setting.size.x, setting.size.y}},
            {"keeps_min_coherence", setting.keepsMinimum}};
}

}  // namespace ivis::optimize
