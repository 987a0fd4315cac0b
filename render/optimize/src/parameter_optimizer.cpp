#include <ivis/optimize/parameter_optimizer.h>

#include <ivis/core/errors.h>
#include <ivis/optimize/curved_ray_gradient.h>
#include <ivis/render/method_registry.h>

#include <cmath>

namespace ivis::optimize {

double goldenSectionMaximize(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                             int* evaluations)
{
    const double invPhi = 2.0 / (1.0 + std::sqrt(5.0));
    double x2 = hi - (hi - lo) * invPhi, x3 = lo + (hi - lo) * invPhi;
    double f2 = f(x2), f3 = f(x3);
    int calls = 2;
    while (hi - lo >= tolerance) {
        if (f2 > f3) {  // the maximum lies in [lo, x3]
            hi = x3;
            x3 = x2;
            f3 = f2;
            x2 = hi - (hi - lo) * invPhi;
            f2 = f(x2);
        } else {  // in [x2, hi]
            lo = x2;
            x2 = x3;
            f2 = f3;
            x3 = lo + (hi - lo) * invPhi;
            f3 = f(x3);
        }
        ++calls;
    }
    if (evaluations) *evaluations += calls;
    return 0.5 * (lo + hi);
}

AscentResult optimizeParameters(const EnergyEvaluator& evaluator, const core::Camera& camera,
                                const render::MethodPtr& start, const AscentOptions& options,
                                core::Interrupter* interrupter)
{
    AscentResult result;
    result.method = start;
    const ViewSamples samples(evaluator.scene(), camera, evaluator.options().resolution, start);
    result.value = evaluator.evaluate(samples, start);
    result.evaluations = 1;
    result.energyTrace.push_back(result.value.energy);
    std::vector<double> x = render::optimisedParameters(*start);
    if (x.empty()) return result;

    const render::MethodInfo& info = start->info();
    const bool analytic = info.tangentLinearGradient && evaluator.options().kind == EnergyKind::Scalar &&
                          options.gradient != GradientMode::ForwardDifference;
    if (options.gradient == GradientMode::Analytic && !analytic)
        throw ValueError("the analytic gradient exists only for the curved-ray methods with the scalar energy");
    auto methodAt = [&](const std::vector<double>& point) { return render::withOptimisedParameters(*start, point); };
    auto energyAt = [&](const std::vector<double>& point) {
        if (interrupter && interrupter->wasInterrupted()) throw Cancelled("parameter ascent cancelled");
        ++result.evaluations;
        return evaluator.evaluate(samples, methodAt(point));
    };
    const render::LineSearch search = info.lineSearch.value_or(options.lineSearch);

    // Start from the best of the start and an even scan of the scanned parameter's range.
    if (const render::ParameterSpec* scanned = info.parameter(info.scannedParameter);
        scanned && options.scanSamples > 1) {
        std::size_t component = 0;  // the scanned parameter's place in x
        for (const render::ParameterSpec& spec : info.parameters) {
            if (&spec == scanned) break;
            if (spec.optimised) component += spec.defaults.size();
        }
        const int count = options.scanSamples;
        for (int k = 0; k < count; ++k) {
            std::vector<double> point = x;
            point[component] = scanned->lo + double(scanned->hi - scanned->lo) * k / (count - 1);
            const EnergyValue value = energyAt(point);
            if (!(value.energy > result.value.energy)) continue;
            x = point;
            result.value = value;
            result.method = methodAt(x);
        }
        if (result.value.energy > result.energyTrace.back()) result.energyTrace.push_back(result.value.energy);
    }

    for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
        std::vector<double> gradient(x.size(), 0.0);
        if (analytic) {
            gradient = curvedRayGradient(evaluator, camera, methodAt(x));
            ++result.evaluations;
        } else {
            for (std::size_t i = 0; i < x.size(); ++i) {
                std::vector<double> shifted = x;
                shifted[i] += options.differenceStep;
                gradient[i] = (energyAt(shifted).energy - result.value.energy) / options.differenceStep;
            }
        }
        if (search.unitDirection) {
            double norm = 0.0;
            for (double g : gradient) norm += g * g;
            norm = std::sqrt(norm);
            if (!(norm > 0.0)) break;
            for (double& g : gradient) g /= norm;
        }
        auto along = [&](double t) {
            std::vector<double> point = x;
            for (std::size_t i = 0; i < x.size(); ++i) point[i] += t * gradient[i];
            return point;
        };
        const double t = goldenSectionMaximize([&](double s) { return energyAt(along(s)).energy; }, 0.0,
                                               search.maxStep, search.tolerance);
        const EnergyValue candidate = energyAt(along(t));
        ++result.iterations;
        if (!(candidate.energy > result.value.energy)) break;
        x = along(t);
        result.value = candidate;
        result.method = methodAt(x);
        result.energyTrace.push_back(candidate.energy);
    }
    return result;
}

}  // namespace ivis::optimize
