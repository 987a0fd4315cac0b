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

}  // namespace ivis::optimize
