#include <ivis/render/framing.h>

#include <ivis/core/errors.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ivis::render {

core::Camera fitCamera(const core::Camera& camera, const PictureExtent& extent, double aspect, bool* fits)
{
    if (!(aspect > 0.0 && std::isfinite(aspect))) throw ValueError("aspect ratio " + std::to_string(aspect) + " must be positive");
    // Per axis: imagePlane / halfHeight + fixed <= the image's half extent - margin (half-heights).
    const glm::dvec2 room = glm::dvec2(aspect, 1.0) - kFramingMargin - extent.fixed;
    if (!(room.x > 0.0 && room.y > 0.0)) {
        char text[240];
        if (std::max(extent.fixed.x, extent.fixed.y) > 0.0)
            std::snprintf(text, sizeof text,
                          "the picture cannot be framed: its fixed-size part (the rings) reaches %.2f image "
                          "half-heights, leaving no room for the object; fix the field of view instead",
                          std::max(extent.fixed.x, extent.fixed.y));
        else
            std::snprintf(text, sizeof text,
                          "the picture cannot be framed: its width is %.4g of its height, which leaves no room for the "
                          "object within the frame's margin; widen it or fix the field of view instead",
                          aspect);
        throw ValueError(text);
    }
    // The image centred on the picture's scaling part; the fixed part lies round it on every side.
    const glm::dvec2 centre = 0.5 * (extent.lo + extent.hi), half = 0.5 * (extent.hi - extent.lo);
    const double needed = std::max(half.x / room.x, half.y / room.y);
    const double widest = widestFramedHalfHeight(camera);
    const bool fit = needed <= widest && std::isfinite(centre.x) && std::isfinite(centre.y);  // false for NaN too
    if (fits) *fits = fit;
    const double halfHeight = fit ? std::max(needed, 1e-3 * widest) : widest;
    core::Camera framed = camera;
    if (camera.orthographic) framed.orthoHalfHeight = halfHeight;
    else framed.fovYDeg = 2.0 * std::atan(halfHeight) * 180.0 / M_PI;
    framed.windowCentre = fit ? centre : glm::dvec2(0.0);
    return framed;
}

core::Camera frameView(const RenderScene& scene, const core::Camera& camera, const Method& method, double aspect,
                       bool* fits)
{
    return fitCamera(camera, method.pictureExtent(scene, camera), aspect, fits);
}

}  // namespace ivis::render
