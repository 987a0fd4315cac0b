#include "view_optimiser.h"

#include <ivis/optimize/energy.h>
#include <ivis/optimize/parameter_optimizer.h>
#include <ivis/optimize/viewpoint_annealing.h>

#include <chrono>
#include <cstdio>

namespace ivis::app {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string describeParams(const render::MethodParams& params)
{
    char text[160];
    switch (params.method) {
    case render::Method::InverseVis: std::snprintf(text, sizeof text, "alpha %.3f", params.curved.alpha); break;
    case render::Method::InverseVisAdaptive:
        std::snprintf(text, sizeof text, "profile %.3f %.3f %.3f", params.profile.coefficients[0],
                      params.profile.coefficients[1], params.profile.coefficients[2]);
        break;
    case render::Method::Mirror:
        std::snprintf(text, sizeof text, "w %.3f %.3f %.3f %.3f %.3f", params.mirror.w[0], params.mirror.w[1],
                      params.mirror.w[2], params.mirror.w[3], params.mirror.w[4]);
        break;
    default: std::snprintf(text, sizeof text, "no parameters"); break;
    }
    return text;
}

}  // namespace

ViewOptimiser parameterOptimiser(const OptimiserSettings& settings)
{
    return [settings](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>&) {
        const auto begin = std::chrono::steady_clock::now();
        const render::EnergyEvaluator evaluator(
            scene, settings.optimization.energyOptions(settings.resolution, settings.importanceRange));
        const render::EnergyValue before = evaluator.evaluate(start.camera, start.method);
        const render::AscentResult ascent =
            render::optimizeParameters(evaluator, start.camera, start.method, settings.optimization.ascentOptions());
        OptimiserResult result;
        result.state = {start.camera, ascent.params};
        result.energyBefore = before.energy;
        result.energyAfter = ascent.value.energy;
        result.evaluations = ascent.evaluations + 1;
        result.seconds = secondsSince(begin);
        char text[320];
        std::snprintf(text, sizeof text, "optimised %s: %s -> %s, %s energy %.4f -> %.4f (%d evaluations, %.1f s)",
                      render::toString(start.method.method), describeParams(start.method).c_str(),
                      describeParams(ascent.params).c_str(), settings.optimization.energy.c_str(), result.energyBefore,
                      result.energyAfter, result.evaluations, result.seconds);
        result.summary = text;
        return result;
    };
}

ViewOptimiser viewpointOptimiser(const OptimiserSettings& settings)
{
    return [settings](const render::RenderScene& scene, const ViewState& start, const std::atomic<bool>&) {
        const auto begin = std::chrono::steady_clock::now();
        const render::EnergyEvaluator evaluator(
            scene, settings.optimization.energyOptions(settings.resolution, settings.importanceRange));
        const glm::dvec2 angles = start.camera.angles();
        const render::EnergyValue before = evaluator.evaluate(start.camera, start.method);
        const auto ascentEvaluator =
            settings.optimization.ascentEvaluator(scene, settings.resolution, settings.importanceRange);
        const render::AnnealingResult annealing = render::annealViewpoint(
            evaluator, start.method, settings.optimization.annealingOptions(angles.x, angles.y, start.camera.fovYDeg),
            settings.optimization.ascentOptions(), ascentEvaluator.get());
        const render::VisitedView& best = annealing.bestView();
        OptimiserResult result;
        result.state.camera = render::viewCamera(best.thetaDeg, best.phiDeg, start.camera.fovYDeg);
        result.state.method = best.params;
        result.energyBefore = before.energy;
        result.energyAfter = best.value.energy;
        result.evaluations = annealing.evaluations + 1;
        result.seconds = secondsSince(begin);
        char text[320];
        std::snprintf(text, sizeof text,
                      "annealed view: theta/phi %.1f/%.1f -> %.1f/%.1f, %s, %s energy %.4f -> %.4f (%zu views, %d "
                      "evaluations, %.1f s)",
                      angles.x, angles.y, best.thetaDeg, best.phiDeg, describeParams(best.params).c_str(),
                      settings.optimization.energy.c_str(), result.energyBefore, result.energyAfter,
                      annealing.visited.size(), result.evaluations, result.seconds);
        result.summary = text;
        return result;
    };
}

}  // namespace ivis::app
