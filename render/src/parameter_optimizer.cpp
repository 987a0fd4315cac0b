#include <ivis/render/parameter_optimizer.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>

namespace ivis::render {
namespace {

/// The free parameters of a method as a vector, and back.
std::vector<double> parameterVector(const MethodParams& params)
{
    const auto& a = params.profile.coefficients;
    switch (params.method) {
    case Method::InverseVis: return {params.curved.alpha};
    case Method::InverseVisAdaptive: return {a.begin(), a.end()};
    case Method::Mirror: return {params.mirror.w.begin(), params.mirror.w.end()};
    default: return {};
    }
}

MethodParams withParameters(MethodParams params, const std::vector<double>& x, const AscentOptions& options)
{
    switch (params.method) {
    case Method::InverseVis: params.curved.alpha = float(std::clamp(x[0], 0.0, options.maxAlpha)); break;
    case Method::InverseVisAdaptive:
        for (std::size_t i = 0; i < params.profile.coefficients.size(); ++i) params.profile.coefficients[i] = float(x[i]);
        break;
    case Method::Mirror:
        for (std::size_t i = 0; i < params.mirror.w.size(); ++i) params.mirror.w[i] = float(x[i]);
        break;
    default: break;
    }
    return params;
}

}  // namespace

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
                                const MethodParams& start, const AscentOptions& options)
{
    AscentResult result;
    result.params = start;
    const ViewSamples samples(evaluator.scene(), camera, evaluator.options().resolution, start);
    result.value = evaluator.evaluate(samples, start);
    result.evaluations = 1;
    result.energyTrace.push_back(result.value.energy);
    std::vector<double> x = parameterVector(start);
    if (x.empty()) return result;

    const bool analytic = start.curvedRays() && evaluator.options().kind == EnergyKind::Scalar &&
                          options.gradient != GradientMode::ForwardDifference;
    if (options.gradient == GradientMode::Analytic && !analytic)
        throw ValueError("the analytic gradient exists only for the curved-ray methods with the scalar energy");
    auto paramsAt = [&](const std::vector<double>& point) { return withParameters(start, point, options); };
    auto energyAt = [&](const std::vector<double>& point) {
        ++result.evaluations;
        return evaluator.evaluate(samples, paramsAt(point));
    };
    // The adaptive method's ascent follows the unit gradient: its visibility gradient is far
    // smaller than its parameters' useful steps.
    const bool unitDirection = start.method == Method::InverseVisAdaptive;
    const double maxStep = unitDirection ? options.maxProfileStep : options.maxStep;
    const double tolerance = unitDirection ? options.profileTolerance : options.tolerance;

    // InverseVis: start from the best of the start alpha and an even scan of [0, maxScanAlpha].
    if (start.method == Method::InverseVis && options.alphaScanSamples > 1) {
        const int samples = options.alphaScanSamples;
        for (int k = 0; k < samples; ++k) {
            const std::vector<double> point{options.maxScanAlpha * k / (samples - 1)};
            const EnergyValue value = energyAt(point);
            if (!(value.energy > result.value.energy)) continue;
            x = point;
            result.value = value;
            result.params = paramsAt(x);
        }
        if (result.value.energy > result.energyTrace.back()) result.energyTrace.push_back(result.value.energy);
    }

    for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
        std::vector<double> gradient(x.size(), 0.0);
        if (analytic) {
            gradient = evaluator.curvedRayGradient(camera, paramsAt(x));
            ++result.evaluations;
        } else {
            for (std::size_t i = 0; i < x.size(); ++i) {
                std::vector<double> shifted = x;
                shifted[i] += options.differenceStep;
                gradient[i] = (energyAt(shifted).energy - result.value.energy) / options.differenceStep;
            }
        }
        if (unitDirection) {
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
        const double t = goldenSectionMaximize([&](double s) { return energyAt(along(s)).energy; }, 0.0, maxStep,
                                               tolerance);
        const EnergyValue candidate = energyAt(along(t));
        ++result.iterations;
        if (!(candidate.energy > result.value.energy)) break;
        x = along(t);
        result.value = candidate;
        result.params = paramsAt(x);
        result.energyTrace.push_back(candidate.energy);
    }
    return result;
}

}  // namespace ivis::render
