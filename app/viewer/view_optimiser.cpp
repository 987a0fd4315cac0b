#include "view_optimiser.h"

#include "../json_output.h"

#include <ivis/optimize/coherence.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/parameter_optimizer.h>
#include <ivis/optimize/readable_rule.h>
#include <ivis/optimize/view_set.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>

#include <chrono>
#include <cstdio>

namespace ivis::app {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The parameters an optimiser moves, as text ("no parameters" for a method without any).
std::string describeParams(const render::Method& method)
{
    const std::string text = render::describeOptimisedParameters(method);
    return text.empty() ? "no parameters" : text;
}

/// Stops an optimiser when the viewer's cancel flag is set (the window closes).
class CancelFlag final : public core::Interrupter {
public:
    explicit CancelFlag(const std::atomic<bool>& cancel) : mCancel(cancel) {}
    bool wasInterrupted(int /*percent*/) override { return mCancel; }

private:
    const std::atomic<bool>& mCancel;
};

/// The view set of @a annealing (the best view first, each further view with its readable rule),
/// appended to @a result, and a line of what the views show together on @a evaluator's voxels.
std::string addViewSet(const optimize::AnnealingResult& annealing, const optimize::EnergyEvaluator& evaluator,
                       const optimize::AnnealingOptions& options, int count, OptimiserResult& result)
{
    std::vector<std::uint64_t> together;
    std::string each;
    const std::vector<optimize::ReadableView> set = optimize::chooseReadableViewSet(annealing, evaluator, options, count);
    for (const optimize::ReadableView& chosen : set) {
        const optimize::VisitedView& view = annealing.visited[chosen.index];
        result.views.push_back({view.camera, chosen.method});
        together.insert(together.end(), view.value.seenVoxels.begin(), view.value.seenVoxels.end());
        char text[32];
        std::snprintf(text, sizeof text, "%s%.4f", each.empty() ? "" : ", ", view.value.energy);
        each += text;
    }
    char text[160];
    std::snprintf(text, sizeof text, "; %zu views together show %.4f (each %s; the panel's view buttons switch)",
                  set.size(), evaluator.surfaceVoxels()->shareSeen(together).area, each.c_str());
    return text;
}

}  // namespace

ViewOptimiser parameterOptimiser(const OptimiserSettings& settings)
{
    return [settings](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel) {
        CancelFlag interrupter(cancel);
        const auto begin = std::chrono::steady_clock::now();
        const optimize::EnergyEvaluator evaluator(
            scene, settings.optimization.energyOptions(settings.resolution, settings.importanceRange));
        // The optimiser's square samples, framed as the viewer frames the view.
        const core::Camera camera =
            settings.framed ? render::frameView(scene, start.camera, *start.method, 1.0) : start.camera;
        const optimize::EnergyValue before = evaluator.evaluate(camera, start.method);
        const optimize::AscentResult ascent = optimize::optimizeParameters(
            evaluator, camera, start.method, settings.optimization.ascentOptions(), &interrupter);
        OptimiserResult result;
        result.state = {start.camera, ascent.method};
        result.energyBefore = before.energy;
        result.energyAfter = ascent.value.energy;
        result.evaluations = ascent.evaluations + 1;
        result.seconds = secondsSince(begin);
        char text[320];
        std::snprintf(text, sizeof text, "optimised %s: %s -> %s, %s energy %.4f -> %.4f (%d evaluations, %.1f s)",
                      start.method->name().c_str(), describeParams(*start.method).c_str(),
                      describeParams(*ascent.method).c_str(), settings.optimization.energy.c_str(), result.energyBefore,
                      result.energyAfter, result.evaluations, result.seconds);
        result.summary = text;
        return result;
    };
}

ViewOptimiser viewpointOptimiser(const OptimiserSettings& settings)
{
    return [settings](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& cancel) {
        CancelFlag interrupter(cancel);
        const auto begin = std::chrono::steady_clock::now();
        const optimize::EnergyEvaluator evaluator(
            scene, settings.optimization.energyOptions(settings.resolution, settings.importanceRange));
        const glm::dvec2 angles = start.camera.angles();
        const core::Camera camera =
            settings.framed ? render::frameView(scene, start.camera, *start.method, 1.0) : start.camera;
        const optimize::EnergyValue before = evaluator.evaluate(camera, start.method);
        const auto ascentEvaluator =
            settings.optimization.ascentEvaluator(scene, settings.resolution, settings.importanceRange);
        const optimize::AnnealingOptions annealingOptions = settings.optimization.annealingOptions(
            angles, settings.framed ? std::nullopt : std::optional(start.camera.fovYDeg));
        const optimize::AnnealingResult annealing = optimize::annealViewpoint(
            evaluator, start.method, annealingOptions, settings.optimization.ascentOptions(), ascentEvaluator.get(), &interrupter,
            settings.optimization.finalistEvaluator(scene, settings.resolution, settings.importanceRange).get());
        const optimize::VisitedView& best = annealing.bestView();
        const std::string readable = annealing.readable ? ", " + readableSettingLine(*annealing.readable) : "";
        OptimiserResult result;
        result.state.camera = best.camera;
        result.state.method = best.method;
        result.energyBefore = before.energy;
        result.energyAfter = best.value.energy;
        result.evaluations = annealing.evaluations + 1;
        result.seconds = secondsSince(begin);
        char text[320];
        std::snprintf(text, sizeof text,
                      "annealed view: theta/phi %.1f/%.1f -> %.1f/%.1f, %s, %s energy %.4f -> %.4f (%zu views, %d "
                      "evaluations, %.1f s)",
                      angles.x, angles.y, best.thetaDeg, best.phiDeg, describeParams(*best.method).c_str(),
                      settings.optimization.energy.c_str(), result.energyBefore, result.energyAfter,
                      annealing.visited.size(), result.evaluations, result.seconds);
        result.summary = text + readable;
        if (settings.views > 1)
            result.summary += evaluator.surfaceVoxels() ? addViewSet(annealing, evaluator, annealingOptions, settings.views, result)
                                                        : "; several views need the visibility energy";
        return result;
    };
}

ViewOptimiser readableRuleOptimiser(const OptimiserSettings& settings)
{
    return [settings](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>& /*cancel*/) {
        const auto begin = std::chrono::steady_clock::now();
        const core::Camera camera =
            settings.framed ? render::frameView(scene, start.camera, *start.method, 1.0) : start.camera;
        // From the rule's default, as render chooses it: the rule shown may be too loose for this view.
        const std::string& key = start.method->info().readableRuleParameter;
        const render::ParameterSpec* spec = start.method->info().parameter(key);
        const render::MethodPtr fromDefault = spec ? render::withValues(*start.method, {{key, spec->defaults}}) : start.method;
        const glm::ivec2 square(optimize::kCoherenceResolution);  // the frame above is square
        const optimize::ReadableSetting readable =
            optimize::loosestReadable(scene, camera, fromDefault, square, settings.optimization.minCoherence);
        OptimiserResult result;
        result.state = {start.camera, readable.method};
        result.evaluations = 1;
        result.seconds = secondsSince(begin);
        char text[64];
        std::snprintf(text, sizeof text, " (%.1f s)", result.seconds);
        result.summary = readableSettingLine(readable) + text;
        return result;
    };
}

}  // namespace ivis::app
