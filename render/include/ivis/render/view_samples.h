/// @file view_samples.h
/// @brief What an energy evaluation of one view computes once for every parameter value: which
///        pixels see the surface directly and where, and for the others the start of their
///        indirect ray (the hull seed of a curved ray).
/// @note Valid for the parameters it was made with up to the ones an ascent changes (alpha, the
///       alpha profile, the mirror's w): see compatibleWith().
#pragma once

#include <ivis/render/screen_map.h>

#include <vector>

namespace ivis::render {

/// @brief A pixel whose view ray misses the surface.
struct MissedPixel {
    float x = 0.0f, y = 0.0f;  ///< continuous pixel position
    CurvedRayStart start;      ///< the curved ray's start (curved-ray methods only)
};

/// @brief Per-view samples at resolution^2 pixel centres, in row order.
class ViewSamples {
public:
    /// @brief Maps every pixel's view ray; for curved-ray methods keeps only the pixels that meet the hull.
    ViewSamples(const RenderScene& scene, const core::Camera& camera, int resolution, const MethodParams& params);

    /// @brief True when @a params differ from the preparing ones only in what the samples do not depend on.
    bool compatibleWith(const MethodParams& params) const;

    const core::CameraFrame& frame() const { return mFrame; }
    /// @brief Surface points of the direct pixels.
    const std::vector<SurfacePoint>& direct() const { return mDirect; }
    /// @brief Pixels that may show the surface indirectly.
    const std::vector<MissedPixel>& missed() const { return mMissed; }

private:
    core::CameraFrame mFrame;
    MethodParams mParams;
    std::vector<SurfacePoint> mDirect;
    std::vector<MissedPixel> mMissed;
};

}  // namespace ivis::render
