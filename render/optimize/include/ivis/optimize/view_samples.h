/// @file view_samples.h
/// @brief What an energy evaluation of one view computes once for every parameter value: which
///        pixels see the surface directly and where, and for the others the start of their
///        indirect ray (the hull seed of a curved ray). For a method the ascent moves nothing of
///        (the wrap) the indirect pixels are mapped at once, as the picture maps them (adaptive
///        image sampling, render::ScreenMap::mapTile): the energy is then the picture's.
/// @note Valid for the parameters it was made with up to the ones an ascent changes (alpha, the
///       alpha profile, the mirror's w): see compatibleWith().
#pragma once

#include <ivis/render/screen_map.h>

#include <vector>

namespace ivis::optimize {

/// @brief A pixel whose view ray misses the surface.
struct MissedPixel {
    float x = 0.0f, y = 0.0f;  ///< continuous pixel position
    render::CurvedRayStart start;      ///< the curved ray's start (curved-ray methods only)
};

/// @brief Per-view samples at resolution^2 pixel centres, in row order.
class ViewSamples {
public:
    /// @brief Maps every pixel's view ray; for curved-ray methods keeps only the pixels whose ray
    ///        the method draws, or, where the ascent moves none of its parameters, maps them.
    /// @throw Cancelled once Ctrl-C was pressed (core/interrupt_signal.h)
    ViewSamples(const render::RenderScene& scene, const core::Camera& camera, int resolution,
                const render::MethodPtr& method);

    /// @brief True when @a method differs from the preparing one only in its optimised parameters.
    bool compatibleWith(const render::Method& method) const;

    /// @brief The camera frame at resolution^2 pixels.
    const core::CameraFrame& frame() const { return mFrame; }
    /// @brief Surface points of the direct pixels.
    const std::vector<render::SurfacePoint>& direct() const { return mDirect; }
    /// @brief Pixels that may show the surface indirectly, their rays still to trace (none where
    ///        the pixels are mapped at once).
    const std::vector<MissedPixel>& missed() const { return mMissed; }
    /// @brief Surface points the indirect pixels show, where they are mapped at once (a method the
    ///        ascent moves nothing of); else empty.
    const std::vector<render::SurfacePoint>& indirect() const { return mIndirect; }

private:
    core::CameraFrame mFrame;
    render::MethodPtr mMethod;
    std::vector<render::SurfacePoint> mDirect;
    std::vector<MissedPixel> mMissed;
    std::vector<render::SurfacePoint> mIndirect;
};

}  // namespace ivis::optimize
