#include <ivis/optimize/viewpoint_annealing.h>

#include <ivis/core/errors.h>
#include <ivis/render/framing.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <random>

namespace ivis::optimize {
namespace {

/// A uniform number in [-1, 1] from the generator (portable: no std distribution).
double symmetricUniform(std::mt19937_64& random)
{
    return 2.0 * (double(random() >> 11) * (1.0 / 9007199254740992.0)) - 1.0;
}

/// Measures the @a count visited views of highest energy on @a finalist and makes the best there
/// (the higher energy breaking ties) the result's best.
void chooseAmongFinalists(AnnealingResult& result, int count, const EnergyEvaluator& finalist)
{
    std::vector<std::size_t> order(result.visited.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    const std::size_t kept = std::min(order.size(), std::size_t(count));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return result.visited[a].value.energy > result.visited[b].value.energy;
    });
    result.best = order.front();
    for (std::size_t rank = 0; rank < kept; ++rank) {
        VisitedView& view = result.visited[order[rank]];
        view.finalValue = finalist.evaluate(view.camera, view.method);
        ++result.evaluations;
        if (view.finalValue->energy > result.bestView().finalValue->energy) result.best = order[rank];
    }
}

}  // namespace

void wrapViewAngles(double& theta, double& phi)
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

double degreesBetweenViews(double theta1, double phi1, double theta2, double phi2)
{
    auto direction = [](double theta, double phi) {
        const double t = theta * M_PI / 180.0, p = phi * M_PI / 180.0;
        return glm::dvec3(std::sin(t) * std::sin(p), std::cos(t), std::sin(t) * std::cos(p));
    };
    const double c = glm::dot(direction(theta1, phi1), direction(theta2, phi2));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

std::vector<std::array<double, 2>> cubeViews()
{
    std::vector<std::array<double, 2>> views;
    for (const auto& angles : kAxisViews) views.push_back({angles[0], angles[1]});
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                if ((x != 0) + (y != 0) + (z != 0) < 2) continue;
                core::Camera camera;
                camera.eye = glm::dvec3(x, y, z);
                const glm::dvec2 angles = camera.angles();
                views.push_back({angles.x, angles.y});
            }
    return views;
}

bool acceptsProposal(double gain, double temperature, double acceptanceScale, double draw)
{
    return gain > 0.0 || draw < std::exp(acceptanceScale * gain / temperature);
}

AnnealingResult annealViewpoint(const EnergyEvaluator& evaluator, const render::MethodPtr& start,
                                const AnnealingOptions& options, const AscentOptions& ascent,
                                const EnergyEvaluator* ascentEvaluator, core::Interrupter* interrupter,
                                const EnergyEvaluator* finalistEvaluator)
{
    if (options.steps < 0 || !(options.cooling > 0.0 && options.cooling <= 1.0) || !(options.startTemperature > 0.0))
        throw ValueError("annealing needs steps >= 0, 0 < cooling <= 1 and a positive start temperature");
    const auto clockStart = std::chrono::steady_clock::now();
    std::mt19937_64 random(options.seed);
    AnnealingResult result;

    auto cameraAt = [&](double theta, double phi, const render::Method& method) {
        const core::Camera camera =
            core::Camera::fromAngles(theta, phi, core::kCameraDistance, options.fovYDeg.value_or(core::kDefaultFovYDeg));
        return options.fovYDeg ? camera : render::frameView(evaluator.scene(), camera, method, 1.0);
    };
    // The view of @a ascent's result, framed for its parameters and measured on the full evaluator
    // unless the ascent already did that at this very camera.
    auto measured = [&](VisitedView& view, const AscentResult& ascent, const core::Camera& ascentCamera, bool onFull) {
        view.method = ascent.method;
        view.camera = cameraAt(view.thetaDeg, view.phiDeg, *ascent.method);
        view.value = ascent.value;
        if (onFull && view.camera.fovYDeg == ascentCamera.fovYDeg &&
            view.camera.orthoHalfHeight == ascentCamera.orthoHalfHeight &&
            view.camera.windowCentre == ascentCamera.windowCentre)
            return;
        view.value = evaluator.evaluate(view.camera, ascent.method);
        ++result.evaluations;
    };
    auto visit = [&](double theta, double phi, const render::MethodPtr& method) {
        const core::Camera camera = cameraAt(theta, phi, *method);
        const AscentResult optimised =
            optimizeParameters(ascentEvaluator ? *ascentEvaluator : evaluator, camera, method, ascent, interrupter);
        result.evaluations += optimised.evaluations;
        VisitedView view;
        view.thetaDeg = theta;
        view.phiDeg = phi;
        measured(view, optimised, camera, !ascentEvaluator);
        return view;
    };
    // Records @a view as visited, the best one when it beats every view before it.
    auto keep = [&](const VisitedView& view) {
        result.visited.push_back(view);
        if (view.value.energy > result.bestView().value.energy) result.best = result.visited.size() - 1;
    };

    if (interrupter) interrupter->start("viewpoint annealing");
    if (options.startAtBestCubeView) {
        for (const auto& angles : cubeViews()) keep(visit(angles[0], angles[1], start));
    } else {
        keep(visit(options.startThetaDeg, options.startPhiDeg, start));
    }
    result.visited[result.best].accepted = true;
    VisitedView current = result.bestView();
    double temperature = options.startTemperature;
    for (int step = 0; step < options.steps; ++step) {
        double theta = current.thetaDeg + options.neighbourhoodDeg * symmetricUniform(random);
        double phi = current.phiDeg + options.neighbourhoodDeg * symmetricUniform(random);
        wrapViewAngles(theta, phi);
        VisitedView proposal = visit(theta, phi, current.method);
        const double gain = proposal.value.energy - current.value.energy;
        const double draw = 0.5 * (symmetricUniform(random) + 1.0);
        proposal.accepted = acceptsProposal(gain, temperature, options.acceptanceScale, draw);
        keep(proposal);
        if (proposal.accepted) current = proposal;
        temperature *= options.cooling;
        if (interrupter && interrupter->wasInterrupted(100 * (step + 1) / std::max(1, options.steps)))
            throw Cancelled("viewpoint annealing cancelled");
    }
    double polishStep = options.polishDeg;
    for (int round = 0; polishStep > 0.0 && round < options.polishRounds; ++round, polishStep *= 0.5) {
        const VisitedView centre = result.bestView();
        for (const auto& [dTheta, dPhi] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}) {
            double theta = centre.thetaDeg + polishStep * dTheta;
            double phi = centre.phiDeg + polishStep * dPhi;
            wrapViewAngles(theta, phi);
            VisitedView view = visit(theta, phi, centre.method);
            view.polish = true;
            keep(view);
        }
    }
    if (finalistEvaluator && options.finalists > 1) chooseAmongFinalists(result, options.finalists, *finalistEvaluator);
    if (ascentEvaluator) {  // the winner's parameters, ascended on the full energy
        VisitedView& best = result.visited[result.best];
        const AscentResult polished = optimizeParameters(evaluator, best.camera, best.method, ascent, interrupter);
        result.evaluations += polished.evaluations;
        measured(best, polished, best.camera, true);
    }
    std::optional<EnergyEvaluator> hotSpotMeasure;  // the hot-spot rule's, where it ran
    if (options.hotSpotViews > 0 && evaluator.options().kind == EnergyKind::Scalar) {
        EnergyOptions judged;  // the reported measures' grid, with the energy's importance
        judged.reveal = true;
        judged.importanceRange = evaluator.options().importanceRange;
        const EnergyEvaluator& measure = hotSpotMeasure.emplace(evaluator.scene(), judged);
        if (measure.revealMeasure() && measure.revealMeasure()->regionCount() > 0) {
            result.hotSpots = chooseHotSpotView(result.visited, result.best, measure, options.hotSpotViews, interrupter);
            if (!result.hotSpots->reads) {
                // None of the search's views reads: views that show every hot spot side-on, visited
                // now (they become the best view only where one reads or comes nearer to reading).
                const std::size_t from = result.visited.size();
                const std::vector<HotSpotFacing> facings =
                    hotSpotFacings(evaluator.scene().mesh(), *measure.revealMeasure());
                for (const auto& [theta, phi] : sideOnViews(facings, 2 * options.hotSpotViews))
                    result.visited.push_back(visit(theta, phi, result.bestView().method));
                result.hotSpots = betterHotSpotChoice(
                    *result.hotSpots,
                    chooseHotSpotView(result.visited, result.best, measure, options.hotSpotViews, interrupter, from));
            }
            if (!result.hotSpots->reads && result.hotSpots->chosen &&
                result.hotSpots->shortfall <= kHotSpotRoundShortfall) {
                // Nor do those, but one comes near: that view with a tighter rule, then its close
                // neighbours, each visited and judged in turn up to the first that reads.
                for (const CandidateView& view : viewsRoundTheNearest(result.visited[*result.hotSpots->chosen])) {
                    result.visited.push_back(visit(view.thetaDeg, view.phiDeg, view.method));
                    result.hotSpots = betterHotSpotChoice(
                        *result.hotSpots, chooseHotSpotView(result.visited, result.best, measure, 1, interrupter,
                                                            result.visited.size() - 1, 0.0));
                    if (result.hotSpots->reads) break;
                }
            }
            if (result.hotSpots->chosen) result.best = *result.hotSpots->chosen;
        }
    }
    if (options.readableResolution > 0 && !start->info().readableRuleParameter.empty()) {
        VisitedView& best = result.visited[result.best];
        // Where the hot-spot rule chose a view that reads, a looser rule must keep its hot spots one
        // place, judged at the measure's size (a looser rule draws more of a ring's outer edge,
        // which can carry a sliver of a hot spot apart from the rest); where it chose the view
        // nearest to reading, no rule looser than the one it was judged with.
        std::function<bool(const render::MethodPtr&)> keepsHotSpots;
        if (result.hotSpots && result.hotSpots->reads)
            keepsHotSpots = [&](const render::MethodPtr& method) {
                return hotSpotsReadIn(*hotSpotMeasure, cameraAt(best.thetaDeg, best.phiDeg, *method), method,
                                      options.readableResolution);
            };
        else if (result.hotSpots && result.hotSpots->chosen)
            keepsHotSpots = [](const render::MethodPtr&) { return false; };
        result.readable = loosestReadable(evaluator.scene(), best.camera, best.method,
                                          {options.readableResolution, options.readableResolution}, options.minCoherence,
                                          keepsHotSpots);
        if (result.readable->method != best.method) {
            best.method = result.readable->method;
            best.camera = cameraAt(best.thetaDeg, best.phiDeg, *best.method);
            best.value = evaluator.evaluate(best.camera, best.method);
            ++result.evaluations;
        }
    }
    if (interrupter) interrupter->end();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart).count();
    return result;
}

}  // namespace ivis::optimize
