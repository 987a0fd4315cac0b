/// @file optimization_options.h
/// @brief Command-line options shared by `optimize` and `evaluate`: the energy, the annealing
///        schedule and the parameter ascent.
#pragma once

#include <ivis/optimize/energy.h>
#include <ivis/optimize/viewpoint_annealing.h>

#include <CLI/CLI.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ivis::app {

/// @brief CLI11's check of an optimisation resolution (rays per side), as the energy takes it.
CLI::Validator optimizationResolutionRange();

/// @brief Energy, annealing and ascent settings as given on the command line.
struct OptimizationOptions {
    std::string energy = "visibility";
    float gamma = 1.0f;
    int visibilityResolution = 200;     ///< grid of the reported visibility measure (the paper's)
    int optVisibilityResolution = 0;    ///< grid of the optimised energy; 0: see energyOptions()
    std::uint64_t seed = 1;
    int steps = 20;
    double cooling = 0.9;
    std::string gradient = "auto";
    int ascentIterations = 3;
    int ascentResolution = 0;           ///< rays per side of the per-view ascent; 0: the optimisation's
    int alphaScan = 0;                  ///< InverseVis alphas scanned before each ascent; 0: none
    int finalists = 5;                  ///< best annealed views measured again at finalistResolution; 0, 1: none
    double polishDeg = 16.0;            ///< first step of the compass search after the proposals; 0: none
    int finalistResolution = 200;       ///< rays per side of that measurement
    double minCoherence = optimize::kDefaultMinCoherence;         ///< the coherence the readable rule keeps; 0: no readable rule
    int hotSpotViews = 8;               ///< views the hot-spot rule judges (scalar energy); 0: no hot-spot rule

    /// @brief Registers --energy, --gamma, --visibility-res, --opt-visibility-res, --seed, --steps,
    ///        --cooling, --polish, --gradient, --ascent-iterations, --ascent-res, --alpha-scan, --finalists,
    ///        --finalist-res, --min-coherence, --hot-spot-views.
    void addTo(CLI::App& command);
    /// @brief These settings keyed by their flags ({"--steps": 20, ...}; an unset default null).
    nlohmann::json settingsJson() const;
    /// @brief Refuses a flag given that no method of @a methods at any of @a optResolutions uses:
    ///        --gamma without the scalar energy, --gradient analytic without it or with a method
    ///        whose gradient is not analytic, --alpha-scan and --min-coherence when no method has
    ///        the parameter they set, --ascent-res not below an --opt-res.
    /// @throw ValueError naming the flag and why it does nothing
    void checkUsedBy(const std::vector<render::MethodPtr>& methods, const std::vector<int>& optResolutions) const;
    /// @brief The energy the optimisation maximises at @a resolution rays per side, importance
    ///        @a range. Its visibility grid is --opt-visibility-res, by default resolution / 2 but at
    ///        most --visibility-res: a grid with more marked voxels than rays rewards spreading the
    ///        rays anywhere rather than covering the surface (docs/optimisation.md).
    optimize::EnergyOptions energyOptions(int resolution, const core::ScalarRange& range) const;
    /// @brief The reported measure at @a resolution rays per side: the visibility grid is
    ///        --visibility-res (the paper's 200), whatever the optimisation used.
    optimize::EnergyOptions measureOptions(int resolution, const core::ScalarRange& range) const;
    /// @brief Annealing options starting at @a startAngles (theta, phi; none: at the best axis view)
    ///        with the fixed field of view @a fovYDeg (none: each view framed for its method); the
    ///        readable rule keeps the coherence of the measure's 1000 x 1000 picture.
    optimize::AnnealingOptions annealingOptions(std::optional<glm::dvec2> startAngles,
                                                std::optional<double> fovYDeg) const;
    /// @brief Ascent options (gradient mode, line searches, alpha scan).
    optimize::AscentOptions ascentOptions() const;
    /// @brief The evaluator of the per-view parameter ascent when --ascent-res is below
    ///        @a resolution (annealViewpoint's ascentEvaluator), else null.
    std::unique_ptr<optimize::EnergyEvaluator> ascentEvaluator(const render::RenderScene& scene, int resolution,
                                                             const core::ScalarRange& range) const;
    /// @brief The evaluator that ranks the finalists (annealViewpoint's finalistEvaluator) when
    ///        --finalists is above 1 and --finalist-res above @a resolution, else null.
    std::unique_ptr<optimize::EnergyEvaluator> finalistEvaluator(const render::RenderScene& scene, int resolution,
                                                               const core::ScalarRange& range) const;

private:
    CLI::App* mCommand = nullptr;  ///< the command addTo registered the flags on (what was given)
};

}  // namespace ivis::app
