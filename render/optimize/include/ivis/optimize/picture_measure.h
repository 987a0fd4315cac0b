/// @file picture_measure.h
/// @brief The visibility measures of a rendered picture from its own layers: the surface points P
///        of its direct and indirect pixels counted on an evaluator's grids (docs/measures.md),
///        instead of tracing the view again.
#pragma once

#include <ivis/core/image.h>
#include <ivis/optimize/energy.h>

namespace ivis::optimize {

/// @brief Surface visibility, front-only visibility and, where @a evaluator has them, the
///        paper-literal figure and the hot-spot reveal of the picture whose "region" and "P.X",
///        "P.Y", "P.Z" layers are @a layers (render::renderImage's): its pixels are the measure's.
/// @throw ValueError for an evaluator of the scalar kind
EnergyValue measurePicture(const EnergyEvaluator& evaluator, const core::ImageLayers& layers);

}  // namespace ivis::optimize
