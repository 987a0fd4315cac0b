/// @file adaptive_sampling.h
/// @brief Adaptive image sampling of a curved-ray method with closest-approach seeds (the wrap;
///        docs/rendering.md, "Adaptive image sampling"): within a tile, view rays are seeded on a lattice refined only where the
///        seeds' valley bottoms are not smooth or a region's edge passes. Between smooth lattice
///        points each pixel seeks its own seed near the bottom the lattice predicts and traces its
///        own ray; blocks whose lattice rays all miss are background; the stability rule probes
///        only the rays whose neighbours' landings bend near its limit. Direct pixels are exact.
#pragma once

#include <ivis/render/curved_ray_method.h>
#include <ivis/render/pixel_mapping.h>

#include <glm/vec2.hpp>

#include <algorithm>
#include <cstddef>

namespace ivis::render {

class ScreenMap;

/// @brief A rectangle of pixels of a picture: columns x0 .. x0 + width - 1, rows y0 .. y0 + height - 1.
struct PixelTile {
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

/// @brief Pixels a tile of adaptive sampling spans on each side: its coarsest lattice step.
inline constexpr int kAdaptiveTileSize = 16;

/// @brief Tiles across @a pixels pixels (the last one may be narrower).
inline int tilesAcross(int pixels) { return (pixels + kAdaptiveTileSize - 1) / kAdaptiveTileSize; }

/// @brief Tile @a index, in row order, of a @a width x @a height picture cut into tiles of
///        kAdaptiveTileSize from the top left (the last column and row clipped to the picture), as
///        the renderer maps them.
inline PixelTile tileAt(int index, int width, int height)
{
    const int columns = tilesAcross(width);
    const int x0 = index % columns * kAdaptiveTileSize, y0 = index / columns * kAdaptiveTileSize;
    return {x0, y0, std::min(kAdaptiveTileSize, width - x0), std::min(kAdaptiveTileSize, height - y0)};
}

/// @brief How adaptive image sampling samples.
struct AdaptiveSampling {
    bool enabled = true;  ///< false: every pixel's ray seeded, traced and judged on its own (the full trace)
    /// A block's inner pixels seek their valley bottoms (findClosestApproachNear) only near the
    /// bottom interpolated from its lattice (biquadratic through its nine points), when the
    /// bilinear map of its corners' bottoms meets its edges' midpoints and centre within this many
    /// fine voxels along the view rays.
    float bottomTolerance = 1.0f;
    /// A block is background without its inner pixels traced when its nine lattice rays miss,
    /// have no seed or have seeds this far beyond their rings (in ring coordinates, 1 at the edge).
    float beyondRingMargin = 0.25f;
    /// A landed ray is drawn without the stability rule's probes when its neighbours' landings
    /// bend, scaled to the probes' step, by at most this share of the rule's largest bend.
    float clearlyStableShare = 0.2f;
};

/// @brief What one tile's sampling did, for the statistics.
struct TileCounts {
    std::size_t raysTraced = 0;         ///< curved rays integrated (not counting the stability rule's probes)
    std::size_t steps = 0;              ///< their integration steps
    std::size_t seedsInterpolated = 0;  ///< pixels whose seeds came from the lattice
    std::size_t pixelsSkipped = 0;      ///< pixels set to background from the lattice, no ray of their own
};

/// @brief The mappings of every pixel of @a tile (row-major into @a mappings, tile.width per row)
///        at continuous positions (x, y) + @a offset, the curved rays of @a rays sampled adaptively
///        (blocks from kAdaptiveTileSize down to 2 pixels, where every pixel has its own seed).
void mapTileAdaptively(const ScreenMap& screen, const CurvedRayMap& rays, const AdaptiveSampling& options,
                       const PixelTile& tile, const glm::dvec2& offset, DistanceField::Sampler& sampler,
                       PixelMapping* mappings, TileCounts& counts);

}  // namespace ivis::render
