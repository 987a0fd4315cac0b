/// @file viewpoint_annealing.h
/// @brief Simulated annealing of the camera on the sphere of radius 2.5 (docs/method.md, "Viewpoint
///        optimisation"): neighbours within +-60 degrees in polar and azimuth angle, acceptance
///        exp(10 (E_new - E_old) / T), T_k = T0 * cooling^k; the method's parameters are optimised
///        at every proposal before its energy is measured. Beyond the paper (AnnealingOptions): a
///        start at the best of the 26 cube views, a compass search round the best view, finalists.
///        Each view is framed for its method (render::frameView, a square image) unless the field
///        of view is fixed: the ascent runs at the view framed for the parameters it starts from,
///        and the view's energy is that of the view framed for the parameters it ends with (they
///        differ only when the framing moves with the optimised parameters: the mirror's w).
/// @note Deterministic for a seed (std::mt19937_64 and fixed-order reductions).
#pragma once

#include <ivis/optimize/hot_spot_rule.h>
#include <ivis/optimize/parameter_optimizer.h>
#include <ivis/optimize/readable_rule.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace ivis::optimize {

/// @brief Annealing schedule and start.
struct AnnealingOptions {
    int steps = 20;                  ///< proposals after the start view
    double neighbourhoodDeg = 60.0;  ///< proposal range in each angle
    double startTemperature = 1.0;
    double cooling = 0.9;            ///< T_k = startTemperature * cooling^k
    double acceptanceScale = 10.0;   ///< the 10 in exp(10 dE / T)
    double startThetaDeg = 90.0;
    double startPhiDeg = 0.0;
    bool startAtBestCubeView = false;  ///< start at the best of cubeViews() instead (the start angles unused)
    std::optional<double> fovYDeg;  ///< a fixed vertical field of view; empty: each view framed
    std::uint64_t seed = 1;
    int finalists = 0;  ///< with a finalist evaluator: this many best views are measured again on it, its best wins
    double polishDeg = 0.0;  ///< after the proposals, a compass search round the best view: steps of this, halved each round; 0: none
    int polishRounds = 3;    ///< the compass search's rounds (4 views each)
    int readableResolution = 0;  ///< pixels per side of the picture the readable rule keeps coherent (loosestReadable); 0: no readable rule
    double minCoherence = kDefaultMinCoherence;  ///< the coherence that step keeps
    int hotSpotViews = 0;  ///< with the scalar energy: the hot-spot rule judges at most this many views (chooseHotSpotView); 0: no rule
};

/// @brief The six views along the coordinate axes, (theta, phi) in degrees: from +y, -y, +z, +x, -z, -x.
inline constexpr double kAxisViews[6][2] = {{0.0, 0.0}, {180.0, 0.0}, {90.0, 0.0}, {90.0, 90.0}, {90.0, 180.0}, {90.0, -90.0}};

/// @brief The 26 views from the centres of a cube's faces, edges and corners, (theta, phi) in
///        degrees: kAxisViews first, then the 12 edge and 8 corner directions (x, y, z in
///        {-1, 0, 1}, two or three of them nonzero; x varies slowest, z fastest).
std::vector<std::array<double, 2>> cubeViews();

/// @brief Keeps the view angles @a theta and @a phi (degrees) on the sphere: theta reflected into
///        [0, 180] (crossing a pole turns phi by 180 degrees), phi wrapped into [-180, 180].
void wrapViewAngles(double& theta, double& phi);

/// @brief The great-circle angle in degrees between the directions of the views at (theta1, phi1)
///        and (theta2, phi2), all in degrees.
double degreesBetweenViews(double theta1, double phi1, double theta2, double phi2);

/// @brief One evaluated camera position.
struct VisitedView {
    double thetaDeg = 0.0;
    double phiDeg = 0.0;
    core::Camera camera;       ///< the camera it was measured with (framed unless the field of view is fixed)
    EnergyValue value;
    render::MethodPtr method;  ///< the method with the parameters optimised at this view
    bool accepted = false;
    bool polish = false;  ///< a view of the compass search after the proposals (AnnealingOptions::polishDeg)
    std::optional<EnergyValue> finalValue;  ///< its energy on the finalist evaluator (finalists only)
};

/// @brief Every visited view (the start first; with startAtBestCubeView the 26 cube views first,
///        in cubeViews()' order, the best of them the start) and the best one.
struct AnnealingResult {
    std::vector<VisitedView> visited;
    std::size_t best = 0;  ///< index into visited
    std::optional<HotSpotChoice> hotSpots;    ///< the hot-spot rule's choice (when it ran)
    std::optional<ReadableSetting> readable;  ///< the readable rule's choice for the best view (when it ran)
    double seconds = 0.0;
    int evaluations = 0;
    /// @brief The best view.
    const VisitedView& bestView() const { return visited[best]; }
};

/// @brief The Metropolis rule: a proposal that raises the energy is accepted; otherwise it is
///        accepted when @a draw < exp(acceptanceScale * gain / temperature).
/// @param gain E_new - E_current
/// @param temperature current temperature (> 0)
/// @param acceptanceScale the 10 in exp(10 dE / T)
/// @param draw a uniform number in [0, 1]
bool acceptsProposal(double gain, double temperature, double acceptanceScale, double draw);

/// @brief Runs the annealing from the start view with the method of @a start (with
///        AnnealingOptions::startAtBestCubeView, from the cube view of highest energy: a search of
///        a few dozen proposals explores one region of the sphere, and which one its start decides); then,
///        with AnnealingOptions::polishDeg, a compass search round the best view: its four
///        neighbours polishDeg away in theta and in phi, the best of all so far the next centre, the
///        step halved each round (random proposals 60 degrees wide rarely land within a few degrees
///        of a peak).
/// @param interrupter optional progress (percent of the proposals) and cancel
/// @param ascentEvaluator when given (typically fewer rays), each view's parameters are ascended
///        on it and only then measured on @a evaluator, and the best view's parameters are
///        ascended once more on @a evaluator; when null everything uses @a evaluator.
/// @param finalistEvaluator when given (typically more rays) and AnnealingOptions::finalists > 1,
///        the best view is the one of the finalists (the visited views of highest energy) with the
///        highest energy on it: an energy measured on few rays ranks close views only roughly.
///        With AnnealingOptions::hotSpotViews and the scalar energy, the best view is then the
///        hot-spot rule's choice where it makes one (chooseHotSpotView, its hot spots counted on the
///        200^3 grid of the reported measures).
///        Last, with AnnealingOptions::readableResolution, the best view's method gets its loosest
///        readable setting (loosestReadable), and the view is framed and measured again with it.
/// @throw Cancelled when interrupted
AnnealingResult annealViewpoint(const EnergyEvaluator& evaluator, const render::MethodPtr& start,
                                const AnnealingOptions& options = {}, const AscentOptions& ascent = {},
                                const EnergyEvaluator* ascentEvaluator = nullptr,
                                core::Interrupter* interrupter = nullptr,
                                const EnergyEvaluator* finalistEvaluator = nullptr);

}  // namespace ivis::optimize
