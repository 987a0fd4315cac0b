/// @file annealing_plot.h
/// @brief The paper's Fig. 6: camera positions visited by the annealing, on a sphere seen from the
///        front (+z) and from the back (-z), coloured by energy, the optimum ringed in red.
#pragma once

#include <ivis/core/image.h>
#include <ivis/optimize/viewpoint_annealing.h>

namespace ivis::optimize {

/// @brief A 2 size x size picture: front hemisphere left, back hemisphere right (seen from behind).
core::Image plotVisitedViews(const AnnealingResult& result, int size = 512);

}  // namespace ivis::optimize
