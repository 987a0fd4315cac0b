/// @file parameter_optimizer.h
/// @brief Gradient ascent of a method's optimised parameters for one view (docs/method.md,
///        "Optimising alpha"); which parameters move, the gradient and the line search come from
///        the method's description (render::MethodInfo).
/// @note Each ascent step is x <- x + t g, t from a golden-section search on [0, 0.25] that
///       evaluates the TRUE energy, until the bracket is shorter than 0.01 (or the method's own
///       line search); the ascent stops when a line search does not raise the energy. Each
///       view's direct hits and hull seeds are computed once (ViewSamples). Optionally the ascent
///       first scans the method's scanned parameter (AscentOptions::scanSamples): the visibility
///       energy has plateaus in alpha where the gradient is zero.
#pragma once

#include <ivis/core/interrupter.h>
#include <ivis/optimize/energy.h>

#include <functional>
#include <vector>

namespace ivis::optimize {

/// @brief How the gradient is obtained.
enum class GradientMode {
    Auto,              ///< analytic where the method has a tangent-linear gradient and the energy is scalar
    Analytic,          ///< tangent-linear (curved-ray methods, scalar energy only)
    ForwardDifference  ///< (E(x + eps e_i) - E(x)) / eps
};

/// @brief Ascent settings (paper defaults).
struct AscentOptions {
    GradientMode gradient = GradientMode::Auto;
    double differenceStep = 0.025;  ///< forward-difference epsilon
    render::LineSearch lineSearch;  ///< used unless the method has its own
    int maxIterations = 20;
    int scanSamples = 0;  ///< values of the method's scanned parameter tried evenly over its bounds before
                          ///< the ascent, which starts from the best (0: none, the paper's)
};

/// @brief Outcome of one optimisation.
struct AscentResult {
    render::MethodPtr method;
    EnergyValue value;
    int iterations = 0;
    int evaluations = 0;               ///< energy evaluations (gradients included)
    std::vector<double> energyTrace;   ///< energy after each accepted step, starting value first
};

/// @brief Maximises f on [lo, hi] by golden-section search until the bracket is shorter than
///        @a tolerance; returns the bracket's midpoint. Counts calls in @a evaluations.
double goldenSectionMaximize(const std::function<double(double)>& f, double lo, double hi, double tolerance,
                             int* evaluations = nullptr);

/// @brief Optimises the optimised parameters of @a start for @a camera (a method without any is
///        only evaluated).
/// @param interrupter optional cancel, asked before every energy evaluation
/// @throw ValueError for an analytic gradient the method or energy does not have; Cancelled when interrupted
AscentResult optimizeParameters(const EnergyEvaluator& evaluator, const core::Camera& camera,
                                const render::MethodPtr& start, const AscentOptions& options = {},
                                core::Interrupter* interrupter = nullptr);

}  // namespace ivis::optimize
