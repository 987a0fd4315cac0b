/// @file landed_extent.h
/// @brief The reach of what a curved-ray method actually draws (the object and the pixels whose
///        rays land), found by probing a grid of rays over the hull: framing's fit for a method
///        whose indirect region is narrower than its hull (inversevis-wrap's rings).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/picture_extent.h>
#include <ivis/render/render_scene.h>

namespace ivis::render {

/// @brief Probe cells along the longer side of the probed rectangle.
inline constexpr int kLandedExtentProbes = 256;

/// @brief The extent of the mesh united with that of the pixels whose curved rays of @a method
///        land, seen from @a camera: probed on square cells (kLandedExtentProbes along the longer
///        side) over @a bound, which must hold every pixel the method may draw; per side of each
///        axis the outermost landed cell's outer edge plus one cell, never beyond @a bound.
/// @return @a bound itself when it is not finite (it cannot be framed anyway)
PictureExtent landedExtent(const RenderScene& scene, const core::Camera& camera, const CurvedRayMethod& method,
                           const PictureExtent& bound);

}  // namespace ivis::render
