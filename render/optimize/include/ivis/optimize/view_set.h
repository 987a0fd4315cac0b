/// @file view_set.h
/// @brief Several views when one is not enough (docs/optimisation.md, "Several views"): of the
///        views an annealing visited, the few whose pictures together show the most surface,
///        chosen greedily by the area they add.
#pragma once

#include <ivis/optimize/surface_voxels.h>
#include <ivis/optimize/viewpoint_annealing.h>

#include <cstddef>
#include <vector>

namespace ivis::optimize {

/// @brief Indices into @a views of at most @a count views: @a first first, then each time the view
///        whose seen voxels (EnergyValue::seenVoxels, keys of @a surface) add the most area to the
///        views chosen so far; ties go to the earlier view; stops when no view adds any area.
/// @throw ValueError for a count below 1 or a first view out of range
std::vector<std::size_t> chooseViewSet(const std::vector<VisitedView>& views, std::size_t first,
                                       const SurfaceVoxels& surface, int count);

/// @brief One view of a readable set: which visited view, and its method as it is drawn.
struct ReadableView {
    std::size_t index = 0;     ///< into AnnealingResult::visited
    render::MethodPtr method;  ///< the best view's as the annealing left it; a further view's with its own readable rule
};

/// @brief chooseViewSet of @a result on @a evaluator's surface voxels (the best view first), each
///        further view given its loosest readable rule as the annealing gives the best one
///        (@a options' readableResolution and minCoherence; none when readableResolution is 0).
/// @throw ValueError unless @a evaluator measures the visibility energy
std::vector<ReadableView> chooseReadableViewSet(const AnnealingResult& result, const EnergyEvaluator& evaluator,
                                                const AnnealingOptions& options, int count);

}  // namespace ivis::optimize
