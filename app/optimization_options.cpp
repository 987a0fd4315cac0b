#include "optimization_options.h"

#include "cli_checks.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/coherence.h>

#include <algorithm>

namespace ivis::app {

CLI::Validator optimizationResolutionRange()
{
    return CLI::Range(optimize::kMinOptimizationResolution, optimize::kMaxOptimizationResolution);
}

void OptimizationOptions::addTo(CLI::App& command)
{
    mCommand = &command;
    command.add_option("--energy", energy, "Energy to maximise: visibility or scalar")
        ->check(CLI::IsMember({"visibility", "scalar"}))
        ->capture_default_str();
    command.add_option("--gamma", gamma, "Weight of the directly visible part (scalar energy)")
        ->check(finiteRange(0.0, 1000.0))
        ->capture_default_str();
    command.add_option("--visibility-res", visibilityResolution, "Voxels per side of the reported visibility measure's grid")
        ->check(CLI::Range(8, 8192))
        ->capture_default_str();
    command.add_option("--opt-visibility-res", optVisibilityResolution,
                       "Voxels per side of the optimised visibility grid (default: opt-res / 2, at most --visibility-res)")
        ->check(CLI::Range(8, 8192));
    command.add_option("--seed", seed, "Annealing seed (results are deterministic for a seed)")
        ->check(unsigned64())
        ->capture_default_str();
    command.add_option("--steps", steps, "Annealing proposals after the start view")
        ->check(CLI::Range(0, 1000000))
        ->capture_default_str();
    command.add_option("--cooling", cooling, "Temperature factor per step (T_k = cooling^k)")
        ->check(finiteRange(0.0, 1.0))
        ->capture_default_str();
    command.add_option("--polish", polishDeg,
                       "After the proposals, a compass search round the best view: its 4 neighbours this many "
                       "degrees away in theta and phi, the step halved each of 3 rounds (0: none)")
        ->check(finiteRange(0.0, 90.0))
        ->capture_default_str();
    command.add_option("--gradient", gradient, "auto, analytic (inversevis and inversevis-adaptive, scalar energy) or forward differences")
        ->check(CLI::IsMember({"auto", "analytic", "forward"}))
        ->capture_default_str();
    command.add_option("--ascent-iterations", ascentIterations, "Line searches per view at most")
        ->check(CLI::Range(1, 100))
        ->capture_default_str();
    command.add_option("--ascent-res", ascentResolution,
                       "Rays per side of each view's parameter ascent when below --opt-res (the view energy stays at "
                       "--opt-res; the best view's parameters are ascended again there)")
        ->check(optimizationResolutionRange());
    command.add_option("--alpha-scan", alphaScan,
                       "Try this many values of the method's scanned parameter (inversevis: alpha) evenly over its "
                       "bounds before each ascent and start from the best (beyond the paper; default none)")
        ->check(CLI::Range(2, 400));
    command.add_option("--finalists", finalists,
                       "Measure this many best annealed views again with --finalist-res rays per side and keep the "
                       "best there (0 or 1: the annealing's best)")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    command.add_option("--finalist-res", finalistResolution,
                       "Rays per side of the finalists' measurement (none when not above the optimisation's)")
        ->check(optimizationResolutionRange())
        ->capture_default_str();
    command.add_option("--min-coherence", minCoherence,
                       "Readable rule: at the best view, the loosest rule for drawing rays (inversevis-wrap: "
                       "--stable-shift, from an eighth of it to 8 times it) whose picture keeps an estimated mapping "
                       "coherence of at least this (beyond the paper); 0: keep the rule as given")
        ->check(finiteRange(0.0, 1.0))
        ->capture_default_str();
    command.add_option("--hot-spot-views", hotSpotViews,
                       "Hot-spot rule, with the scalar energy: the best view is the best of this many best visited "
                       "views (each at least 20 degrees from those before) whose every hot spot is at least 90% seen "
                       "and reads as one place in a 500 x 500 picture (share in one region at least 0.9, outline "
                       "ratio at most 1.6; beyond the paper); where none does, as many more views that show every "
                       "hot spot side-on are tried; where none of those does either, the judged view nearest to reading "
                       "is taken, unless (where it misses by at most 5% of a bound) the same view with its tightest "
                       "readable rule or one 4 degrees off in theta, phi or both reads; 0: no rule")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
}

nlohmann::json OptimizationOptions::settingsJson() const
{
    auto unlessZero = [](int value) { return value == 0 ? nlohmann::json() : nlohmann::json(value); };
    return {{"--energy", energy},
            {"--gamma", gamma},
            {"--visibility-res", visibilityResolution},
            {"--opt-visibility-res", unlessZero(optVisibilityResolution)},
            {"--seed", seed},
            {"--steps", steps},
            {"--cooling", cooling},
            {"--polish", polishDeg},
            {"--gradient", gradient},
            {"--ascent-iterations", ascentIterations},
            {"--ascent-res", unlessZero(ascentResolution)},
            {"--alpha-scan", unlessZero(alphaScan)},
            {"--finalists", finalists},
            {"--finalist-res", finalistResolution},
            {"--min-coherence", minCoherence},
            {"--hot-spot-views", hotSpotViews}};
}

void OptimizationOptions::checkUsedBy(const std::vector<render::MethodPtr>& methods,
                                      const std::vector<int>& optResolutions) const
{
    auto given = [&](const char* flag) { return mCommand && mCommand->get_option(flag)->count() > 0; };
    auto none = [&](auto has) {
        return std::none_of(methods.begin(), methods.end(), [&](const render::MethodPtr& m) { return has(m->info()); });
    };
    const bool scalar = optimize::parseEnergyKind(energy) == optimize::EnergyKind::Scalar;
    if (given("--gamma") && !scalar)
        throw ValueError("--gamma weights the directly visible part of the scalar energy; --energy is " + energy);
    if (gradient == "analytic") {
        if (!scalar) throw ValueError("--gradient analytic: the gradient is analytic for the scalar energy only");
        for (const render::MethodPtr& m : methods)
            if (!m->info().tangentLinearGradient)
                throw ValueError("--gradient analytic: " + m->name() +
                                 "'s gradient is not analytic (inversevis's and inversevis-adaptive's are)");
    }
    if (given("--alpha-scan") && none([](const render::MethodInfo& i) { return !i.scannedParameter.empty(); }))
        throw ValueError("--alpha-scan: no method given has a parameter to scan (inversevis: alpha)");
    if (given("--hot-spot-views") && hotSpotViews > 0 && !scalar)
        throw ValueError("--hot-spot-views: the hot-spot rule chooses among views by the scalar energy; --energy is " + energy);
    if (given("--min-coherence") && none([](const render::MethodInfo& i) { return !i.readableRuleParameter.empty(); }))
        throw ValueError("--min-coherence: no method given has a rule for drawing rays to loosen (inversevis-wrap: "
                         "--stable-shift)");
    if (ascentResolution > 0 &&
        std::none_of(optResolutions.begin(), optResolutions.end(), [&](int r) { return ascentResolution < r; }))
        throw ValueError("--ascent-res " + std::to_string(ascentResolution) +
                         " is not below --opt-res: the ascent runs at --opt-res");
}

optimize::EnergyOptions OptimizationOptions::energyOptions(int resolution, const core::ScalarRange& range) const
{
    optimize::EnergyOptions options;
    options.kind = optimize::parseEnergyKind(energy);
    options.gamma = gamma;
    options.resolution = resolution;
    options.visibilityResolution = optVisibilityResolution > 0 ? optVisibilityResolution
                                                               : std::clamp(resolution / 2, 8, visibilityResolution);
    options.importanceRange = range;
    return options;
}

optimize::EnergyOptions OptimizationOptions::measureOptions(int resolution, const core::ScalarRange& range) const
{
    optimize::EnergyOptions options = energyOptions(resolution, range);
    options.visibilityResolution = visibilityResolution;
    return options;
}

optimize::AnnealingOptions OptimizationOptions::annealingOptions(std::optional<glm::dvec2> startAngles,
                                                                 std::optional<double> fovYDeg) const
{
    optimize::AnnealingOptions options;
    options.steps = steps;
    options.cooling = cooling;
    options.seed = seed;
    options.finalists = finalists;
    options.polishDeg = polishDeg;
    options.startAtBestCubeView = !startAngles;
    if (startAngles) {
        options.startThetaDeg = startAngles->x;
        options.startPhiDeg = startAngles->y;
    }
    options.fovYDeg = fovYDeg;
    // The rule is judged at the coherence measure's size whatever the picture's (as render judges it).
    options.readableResolution = minCoherence > 0.0 ? optimize::kCoherenceResolution : 0;
    options.minCoherence = minCoherence;
    options.hotSpotViews = hotSpotViews;
    return options;
}

optimize::AscentOptions OptimizationOptions::ascentOptions() const
{
    optimize::AscentOptions options;
    options.gradient = gradient == "analytic" ? optimize::GradientMode::Analytic
                       : gradient == "forward" ? optimize::GradientMode::ForwardDifference
                                               : optimize::GradientMode::Auto;
    options.maxIterations = ascentIterations;
    options.scanSamples = alphaScan;
    return options;
}

std::unique_ptr<optimize::EnergyEvaluator> OptimizationOptions::ascentEvaluator(const render::RenderScene& scene,
                                                                              int resolution,
                                                                              const core::ScalarRange& range) const
{
    if (ascentResolution <= 0 || ascentResolution >= resolution) return nullptr;
    return std::make_unique<optimize::EnergyEvaluator>(scene, energyOptions(ascentResolution, range));
}

std::unique_ptr<optimize::EnergyEvaluator> OptimizationOptions::finalistEvaluator(const render::RenderScene& scene,
                                                                                int resolution,
                                                                                const core::ScalarRange& range) const
{
    if (finalists <= 1 || finalistResolution <= resolution) return nullptr;
    return std::make_unique<optimize::EnergyEvaluator>(scene, energyOptions(finalistResolution, range));
}

}  // namespace ivis::app
