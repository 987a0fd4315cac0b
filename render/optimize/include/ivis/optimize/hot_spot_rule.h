/// @file hot_spot_rule.h
/// @brief The optimisation's hot-spot rule (beyond the paper, docs/optimisation.md, "The hot-spot
///        rule"): with the scalar energy, the best view is the best of the few best distinct visited
///        views whose every hot spot is seen and reads as one place in its picture (docs/measures.md,
///        3 and 4), where one of them does; else the first that reads of views showing every hot
///        spot side-on, then of views round the one nearest to reading; else that nearest one.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/interrupter.h>
#include <ivis/core/triangle_mesh.h>
#include <ivis/optimize/energy.h>
#include <ivis/optimize/hot_spot_shape.h>
#include <ivis/optimize/reveal.h>

#include <glm/vec3.hpp>

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace ivis::optimize {

struct VisitedView;

/// @brief A hot spot counts as seen from this share of its area on (RevealValue::perRegion).
inline constexpr double kMinHotSpotSeen = 0.9;
/// @brief It reads as one place from this share in its largest region (HotSpotShape::largestShare) ...
inline constexpr double kMinHotSpotShare = 0.9;
/// @brief ... up to this outline ratio (HotSpotShape::outlineRatio).
inline constexpr double kMaxHotSpotOutline = 1.6;
/// @brief Views closer than this to one already judged are not judged (the search's neighbours of
///        one view read alike).
inline constexpr double kHotSpotViewSeparationDeg = 20.0;
/// @brief Pixels per side of the pictures the rule judges.
inline constexpr int kHotSpotPictureSize = 500;
/// @brief Degrees in theta, phi or both between the view nearest to reading and the neighbours of
///        it that the rule judges where no view reads (viewsRoundTheNearest).
inline constexpr double kHotSpotNeighbourDeg = 4.0;
/// @brief The views round the nearest are tried only where its hotSpotShortfall is at most this: in
///        sweeps round the nearest views of six meshes (the tighter rule on all, the neighbours on four)
///        they read only round views within 0.025 of reading, and came no nearer round those 0.06 or
///        more from it.
inline constexpr double kHotSpotRoundShortfall = 0.05;

/// @brief A hot spot whose normals, summed by area, come to less than this share of its area faces
///        no one way (it wraps round a tip or a thin part).
inline constexpr double kMinHotSpotFacing = 0.5;
/// @brief A hot spot facing away from the eye within this angle of straight away lies in the middle
///        of the far side, which the wrap spreads along the rings' outer edges: not judged.
inline constexpr double kHotSpotFacingAwayDeg = 60.0;

/// @brief Where a hot spot lies and which way it faces.
struct HotSpotFacing {
    glm::dvec3 centroid{0.0};  ///< area-weighted centre of its triangles
    glm::dvec3 normal{0.0};    ///< unit area-weighted mean normal; zero when it faces no one way
};

/// @brief Each hot spot of @a reveal (in region order) over the triangles of @a mesh whose centroid
///        lies in it.
std::vector<HotSpotFacing> hotSpotFacings(const core::TriangleMesh& mesh, const RevealMeasure& reveal);

/// @brief True when some hot spot of @a facings faces away from the eye of @a camera within
///        kHotSpotFacingAwayDeg of straight away (seen from the eye towards its centroid).
bool someHotSpotFacesAway(const std::vector<HotSpotFacing>& facings, const core::Camera& camera);

/// @brief A hot spot is seen side-on when its mean normal lies within this angle of square to the
///        line from the eye to its centre: half of it seen directly, half in the ring beside it.
inline constexpr double kSideOnDeg = 25.0;
/// @brief Directions tried for side-on views (a Fibonacci lattice on the sphere of views).
inline constexpr int kSideOnLatticeViews = 400;

/// @brief The views (theta, phi in degrees, as core::Camera::fromAngles takes them) from which every
///        hot spot of @a facings is seen side-on (kSideOnDeg), from the eye at core::kCameraDistance:
///        its mean normal, or for one that faces no one way its direction from the hot spots' mean
///        centre (it then lies at the silhouette), square to the line from the eye to its centre.
///        kSideOnLatticeViews directions, the most side-on first (the largest of the hot spots'
///        angles off square the smallest), each at least kHotSpotViewSeparationDeg from those before
///        it, at most @a count; none where no hot spot has a direction.
std::vector<std::array<double, 2>> sideOnViews(const std::vector<HotSpotFacing>& facings, int count);

/// @brief A view to visit: its angles (as core::Camera::fromAngles takes them) and its method.
struct CandidateView {
    double thetaDeg = 0.0;
    double phiDeg = 0.0;
    render::MethodPtr method;
};

/// @brief What the rule tries where none of the views it judged reads, round the one nearest to
///        reading (@a nearest: its angles and method): that view with the tightest rung of its
///        method's readable rule (readableRuleLadder's first, where the method has the rule and the
///        rung is tighter than its own: a tighter rule leaves out a ring's outer edge, which can carry
///        slivers of a hot spot apart from the rest), then its eight neighbours kHotSpotNeighbourDeg
///        apart in theta, in phi or in both, with its method (the angles kept on the sphere:
///        wrapViewAngles).
std::vector<CandidateView> viewsRoundTheNearest(const VisitedView& nearest);

/// @brief What the hot-spot rule chose.
struct HotSpotChoice {
    int judged = 0;                     ///< views whose pictures were judged
    std::optional<std::size_t> chosen;  ///< the visited view taken: the first judged whose hot spots read, else
                                        ///< the judged view nearest to reading (none: no view was judged)
    bool reads = false;                 ///< whether the chosen view's hot spots read as one place
    double shortfall = 1.0;             ///< the chosen view's hotSpotShortfall in its judged picture (0: it reads)
    std::vector<HotSpotShape> shapes;   ///< the chosen view's hot spots in its judged picture
    double energyRatio = 1.0;           ///< the chosen view's energy over the search's best view's
};

/// @brief Of two choices of the rule over other views, the one that reads, else the one nearer to
///        reading (@a first where they tie); the judged views of both counted.
HotSpotChoice betterHotSpotChoice(const HotSpotChoice& first, const HotSpotChoice& second);

/// @brief True when every region of @a seen (RevealValue::perRegion) is at least kMinHotSpotSeen seen
///        and every one of @a shapes has a largest share of at least kMinHotSpotShare and an outline
///        ratio of at most kMaxHotSpotOutline (false without any region).
bool hotSpotsReadAsOnePlace(const std::vector<double>& seen, const std::vector<HotSpotShape>& shapes);

/// @brief How far the hot spots of @a seen and @a shapes are from reading as one place: over the
///        regions, the largest shortfall of a bound relative to the bound ((kMinHotSpotSeen - seen) /
///        kMinHotSpotSeen, the same of the largest share, (outline ratio - kMaxHotSpotOutline) /
///        kMaxHotSpotOutline); 0 exactly where hotSpotsReadAsOnePlace holds, 1 without any region,
///        with a shape missing or with a NaN.
double hotSpotShortfall(const std::vector<double>& seen, const std::vector<HotSpotShape>& shapes);

/// @brief Whether every hot spot (counted as @a measure, an evaluator with the reveal, counts them)
///        reads as one place (hotSpotsReadAsOnePlace) in @a method's @a size x @a size picture from @a camera.
bool hotSpotsReadIn(const EnergyEvaluator& measure, const core::Camera& camera, const render::MethodPtr& method, int size);

/// @brief The hot-spot rule over @a visited from index @a from on: the search's best view (@a best)
///        first where it is among them, then the others by energy, at most @a views views, each at
///        least @a separationDeg from those judged before it and none with a hot spot facing
///        away (someHotSpotFacesAway), judged on a kHotSpotPictureSize picture from its camera with
///        its method (its hot spots counted as @a measure, an evaluator with the reveal, counts
///        them), up to the first whose hot spots read; where none reads, the one nearest to reading
///        (the least hotSpotShortfall, the first judged of those that tie).
/// @param interrupter optional cancel, asked before each picture
/// @throw ValueError when @a measure does not measure the reveal; Cancelled when interrupted
HotSpotChoice chooseHotSpotView(const std::vector<VisitedView>& visited, std::size_t best, const EnergyEvaluator& measure,
                                int views, core::Interrupter* interrupter = nullptr, std::size_t from = 0,
                                double separationDeg = kHotSpotViewSeparationDeg);

/// @brief What the rule chose, as optimize --json reports it: {"judged", "chosen_view" (the index in
///        "visited", null for none), "reads", "shortfall", "energy_ratio", "shapes"}.
nlohmann::json hotSpotChoiceJson(const HotSpotChoice& choice);

}  // namespace ivis::optimize
