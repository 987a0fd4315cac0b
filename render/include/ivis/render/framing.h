/// @file framing.h
/// @brief Fits a camera's field of view and window centre to a method's picture, as ParaView's
///        "reset camera" fits the bounds: the eye, its target and its heading stay; the picture
///        (the object and the method's indirect region: hull, rings or mirror footprint) is
///        centred in the image and fills it up to a margin of kFramingMargin image half-heights
///        on its tighter axis.
/// @note The view axis stays on the target; a picture lying to one side of it is centred by
///       shifting the image window (Camera::windowCentre), as a shift lens does.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/method.h>
#include <ivis/render/picture_extent.h>
#include <ivis/render/render_scene.h>

namespace ivis::render {

/// @brief @a camera with the window centre at the centre of @a extent's scaling part and the
///        vertical field of view (orthographic: the half height) at which @a extent fills an image
///        of width / height @a aspect up to kFramingMargin.
/// @param fits optional output: false when the picture needs more than the widest field of view
///        (widestFramedHalfHeight()) or reaches infinitely far; the camera then has that widest
///        one, centred on the view axis
/// @throw ValueError for a non-positive aspect, or when the fixed part of the extent (the rings)
///        leaves no room within the margin
core::Camera fitCamera(const core::Camera& camera, const PictureExtent& extent, double aspect, bool* fits = nullptr);

/// @brief fitCamera() to @a method's picture of @a scene seen from @a camera (Method::pictureExtent).
core::Camera frameView(const RenderScene& scene, const core::Camera& camera, const Method& method, double aspect,
                       bool* fits = nullptr);

}  // namespace ivis::render
