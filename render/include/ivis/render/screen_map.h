/// @file screen_map.h
/// @brief The map P: I -> S of docs/method.md: for a pixel position, the surface point it shows, by
///        a straight view ray (I+) or by the method's indirect ray (I-).
/// @warning map() is const and thread-safe given one DistanceField::Sampler per thread.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/adaptive_sampling.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/method.h>
#include <ivis/render/pixel_mapping.h>
#include <ivis/render/render_scene.h>

#include <memory>
#include <vector>

namespace ivis::render {

/// @brief P for one camera, image size and method.
class ScreenMap {
public:
    /// @brief Prepares the method's per-view state (e.g. ring radii from the silhouette).
    ScreenMap(const RenderScene& scene, const core::CameraFrame& frame, MethodPtr method);

    /// @brief The surface point shown at continuous pixel position (x, y).
    PixelMapping map(double x, double y, DistanceField::Sampler& sampler) const;
    /// @brief map() of each of @a count pixel positions into @a mappings, the indirect ones traced
    ///        together (IndirectMap::mapMany): what a renderer calls per row.
    void mapMany(const glm::dvec2* positions, std::size_t count, DistanceField::Sampler& sampler,
                 PixelMapping* mappings) const;

    /// @brief map() of every pixel of @a tile at continuous positions (x, y) + @a offset, row-major
    ///        into @a mappings: the rays of a method with closest-approach seeds (the wrap) sampled
    ///        adaptively (mapTileAdaptively) unless @a adaptive is off, every other method's pixels
    ///        row by row with mapMany().
    void mapTile(const PixelTile& tile, const glm::dvec2& offset, const AdaptiveSampling& adaptive,
                 DistanceField::Sampler& sampler, PixelMapping* mappings, TileCounts& counts) const;

    /// @brief The direct part of map(): the surface point the view ray of (x, y) hits, or background.
    PixelMapping directHit(double x, double y) const;
    /// @brief The indirect part of map(), for a pixel whose view ray misses the surface: what the
    ///        method's indirect ray shows there.
    PixelMapping indirect(double x, double y, DistanceField::Sampler& sampler) const;

    /// @brief The curved rays of this view (null unless the method traces curved rays).
    const CurvedRayMap* curvedRays() const { return mCurved; }

private:
    const RenderScene& mScene;
    core::CameraFrame mFrame;
    MethodPtr mMethod;
    std::unique_ptr<IndirectMap> mIndirect;
    const CurvedRayMap* mCurved = nullptr;
};

}  // namespace ivis::render
