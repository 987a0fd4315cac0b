/// @file hot_spot_shape.h
/// @brief Whether each hot spot reads as one place in a picture (docs/measures.md, 4): over the
///        pixels, direct and indirect, that show it, the share in its largest 4-connected region,
///        and that region's outline length over its convex hull's perimeter (a disc: 4/pi, about
///        1.27; a zigzag band or a ragged region: more).
#pragma once

#include <ivis/core/image.h>
#include <ivis/optimize/reveal.h>

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <vector>

namespace ivis::optimize {

/// @brief How one hot spot reads in a picture.
struct HotSpotShape {
    std::size_t pixels = 0;     ///< pixels showing the hot spot
    double largestShare = 0.0;  ///< share of them in their largest 4-connected region (0 when none shows it)
    double outlineRatio = 0.0;  ///< that region's outline (pixel edges) / its convex hull's perimeter (0 when none)
};

/// @brief The shape of each important region of @a reveal (in its order) in a picture's @a layers
///        ("region", "P.X", "P.Y", "P.Z", "scalar"): a pixel shows a region when it shows the
///        surface, its scalar is important and its surface point lies in one of the region's voxels.
std::vector<HotSpotShape> hotSpotShapes(const RevealMeasure& reveal, const core::ImageLayers& layers);

/// @brief The shapes as the measures report them: [{"pixels", "largest_share", "outline_ratio"}, ...].
nlohmann::json hotSpotShapesJson(const std::vector<HotSpotShape>& shapes);

}  // namespace ivis::optimize
