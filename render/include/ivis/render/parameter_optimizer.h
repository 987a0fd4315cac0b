/// @file parameter_optimizer.h
/// @brief Gradient ascent of a method's parameters for one view (METHOD.md, "Optimising alpha"):
///        InverseVis alpha, the mirror's w1..w5, the adaptive InverseVis's alpha profile; the ring
///        map has none (its radii follow the silhouette).
/// @note Each ascent step is x <- x + t g, t from a golden-section search on [0, 0.25] that
///       evaluates the TRUE energy, until the bracket is shorter than 0.01; the ascent stops when a
///       line search does not raise the energy. The adaptive profile steps along the unit
///       gradient, t in [0, 1], bracket 0.1. Each view's direct hits and hull seeds are computed
///       once (ViewSamples). Optionally InverseVis first scans alpha (AscentOptions::alphaScanSamples):
///       the visibility energy has plateaus in alpha where the gradient is zero.
#pragma once

#include <ivis/render/energy.h>

#include <functional>
#include <vector>

namespace ivis::render {

/// @brief How the gradient is obtained.
enum class GradientMode {
    Auto,              ///< analytic for InverseVis + scalar energy, forward differences otherwise
    Analytic,          ///< tangent-linear dE/dalpha (InverseVis, scalar energy only)
    ForwardDifference  ///< (E(x + eps e_i) - E(x)) / eps
};

/// @brief Ascent settings (paper defaults).
struct AscentOptions {
    GradientMode gradient = GradientMode::Auto;
    double differenceStep = 0.025;  ///< forward-difference epsilon
    double maxStep = 0.25;          ///< line search interval [0, maxStep]
    double tolerance = 0.01;        ///< line search stops below this bracket length
    int maxIterations = 20;
    double maxAlpha = 10.0;         ///< alpha is kept in [0, maxAlpha] (rays escape above ~4)
    double maxProfileStep = 1.0;    ///< adaptive InverseVis: line search along the unit gradient on [0, this]
    double profileTolerance = 0.1;  ///< adaptive InverseVis: its line search's final bracket
    int alphaScanSamples = 0;       ///< InverseVis: alphas tried evenly on [0, maxScanAlpha] before the
                                    ///< ascent, which starts from the best (0: none, the paper's)
    double maxScanAlpha = 4.0;      ///< end of that scan (above ~4 rays escape)
};

/// @brief Outcome of one optimisation.
struct AscentResult {
    MethodParams params;
    EnergyValue value;
    int iterations = 0;
    int evaluations = 0;               ///< energy evaluations (gradients included)
    std::vector<double> energyTrace;   ///< energy after each accepted step, starting value first
};

/// @brief Maximises f on [lo, hi] by golden-section search until the bracket is shorter than
///        @a tolerance; returns the bracket's midpoint. Counts calls in @a evaluations.
double goldenSectionMaximize(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                             int* evaluations = nullptr);

/// @brief Optimises the parameters of @a start.method for @a camera (none for front, backfaces,
///        neugebauer: those are only evaluated).
AscentResult optimizeParameters(const EnergyEvaluator& evaluator, const core::Camera& camera,
                                const MethodParams& start, const AscentOptions& options = {});

}  // namespace ivis::render
