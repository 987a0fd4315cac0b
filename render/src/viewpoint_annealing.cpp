#include <ivis/render/viewpoint_annealing.h>

#include <ivis/core/errors.h>

#include <chrono>
#include <cmath>
#include <random>

namespace ivis::render {
namespace {

/// A uniform number in [-1, 1] from the generator (portable: no std distribution).
double symmetricUniform(std::mt19937_64& random)
{
    return 2.0 * (double(random() >> 11) * (1.0 / 9007199254740992.0)) - 1.0;
}

/// Keeps a proposal on the sphere: theta reflected into [0, 180] (crossing a pole turns phi by
/// 180 degrees), phi wrapped into (-180, 180].
void wrapAngles(double& theta, double& phi)
{
    if (theta < 0.0) {
        theta = -theta;
        phi += 180.0;
    } else if (theta > 180.0) {
        theta = 360.0 - theta;
        phi += 180.0;
    }
    phi = std::remainder(phi, 360.0);
}

}  // namespace

bool acceptsProposal(double gain, double temperature, double acceptanceScale, double draw)
{
    return gain > 0.0 || draw < std::exp(acceptanceScale * gain / temperature);
}

core::Camera viewCamera(double thetaDeg, double phiDeg, double fovYDeg)
{
    return core::Camera::fromAngles(thetaDeg, phiDeg, core::kCameraDistance, fovYDeg);
}

AnnealingResult annealViewpoint(const EnergyEvaluator& evaluator, const MethodParams& start,
                                const AnnealingOptions& options, const AscentOptions& ascent,
                                const EnergyEvaluator* ascentEvaluator)
{
    if (options.steps < 0 || !(options.cooling > 0.0 && options.cooling <= 1.0) || !(options.startTemperature > 0.0))
        throw ValueError("annealing needs steps >= 0, 0 < cooling <= 1 and a positive start temperature");
    const auto clockStart = std::chrono::steady_clock::now();
    std::mt19937_64 random(options.seed);
    AnnealingResult result;

    auto visit = [&](double theta, double phi, const MethodParams& params) {
        const core::Camera camera = viewCamera(theta, phi, options.fovYDeg);
        const AscentResult optimised =
            optimizeParameters(ascentEvaluator ? *ascentEvaluator : evaluator, camera, params, ascent);
        result.evaluations += optimised.evaluations;
        VisitedView view;
        view.thetaDeg = theta;
        view.phiDeg = phi;
        view.params = optimised.params;
        view.value = optimised.value;
        if (ascentEvaluator) {
            view.value = evaluator.evaluate(camera, optimised.params);
            ++result.evaluations;
        }
        return view;
    };

    VisitedView current = visit(options.startThetaDeg, options.startPhiDeg, start);
    current.accepted = true;
    result.visited.push_back(current);
    double temperature = options.startTemperature;
    for (int step = 0; step < options.steps; ++step) {
        double theta = current.thetaDeg + options.neighbourhoodDeg * symmetricUniform(random);
        double phi = current.phiDeg + options.neighbourhoodDeg * symmetricUniform(random);
        wrapAngles(theta, phi);
        VisitedView proposal = visit(theta, phi, current.params);
        const double gain = proposal.value.energy - current.value.energy;
        const double draw = 0.5 * (symmetricUniform(random) + 1.0);
        proposal.accepted = acceptsProposal(gain, temperature, options.acceptanceScale, draw);
        result.visited.push_back(proposal);
        if (proposal.value.energy > result.bestView().value.energy) result.best = result.visited.size() - 1;
        if (proposal.accepted) current = proposal;
        temperature *= options.cooling;
    }
    if (ascentEvaluator) {  // the winner's parameters, ascended on the full energy
        VisitedView& best = result.visited[result.best];
        const AscentResult polished =
            optimizeParameters(evaluator, viewCamera(best.thetaDeg, best.phiDeg, options.fovYDeg), best.params, ascent);
        result.evaluations += polished.evaluations;
        best.params = polished.params;
        best.value = polished.value;
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart).count();
    return result;
}

}  // namespace ivis::render
