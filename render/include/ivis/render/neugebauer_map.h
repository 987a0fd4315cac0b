/// @file neugebauer_map.h
/// @brief Geometry of the ring map after Neugebauer et al. (2009): a ring around the projected
///        centre, just outside the silhouette, and a back-side disc on the left of the screen.
/// @note Ring pixel at radius r, in-plane direction u: straight ray from c along
///       u + (2r/(r1+r2) - 1) n, n the view direction (docs/method.md). Back disc pixel at radius r:
///       ray along cos(t) n + sin(t) u', t = 90 deg * r / R, u' mirrored left-right (seen from behind).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/triangle_mesh.h>
#include <ivis/render/picture_extent.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace ivis::render {

/// @brief Ring map parameters (lengths in units of the image half-height).
struct RingParams {
    glm::vec3 centre{0.0f};      ///< projection centre c (normalised coordinates)
    float ringWidth = 0.3f;      ///< r2 - r1
    float silhouetteGap = 0.02f; ///< r1 = silhouette radius around c_D + this gap
    float backRadius = 0.3f;     ///< radius of the back-side disc on the left
};

/// @brief Ring radii and centres in pixels.
struct RingLayout {
    glm::dvec2 centre{0.0};      ///< c_D, projection of the centre c
    double innerRadius = 0.0;    ///< r1, just outside the silhouette
    double outerRadius = 0.0;    ///< r2 = r1 + width
    glm::dvec2 backCentre{0.0};  ///< centre of the back-side disc
    double backRadius = 0.0;
};

/// @brief Lays out the rings for a camera: r1 = largest distance of a projected vertex from c_D
///        plus the gap; the back disc sits in the upper left corner.
RingLayout layoutRings(const core::CameraFrame& frame, const core::TriangleMesh& mesh, const RingParams& params);

/// @brief How far the rings seen from @a camera reach: the disc of the silhouette radius round the
///        projected centre on the image plane, and the gap plus the ring width as a fixed part
///        (the back-side disc always sits in its corner).
PictureExtent ringExtent(const core::Camera& camera, const core::TriangleMesh& mesh, const RingParams& params);

/// @brief Direction of the map ray of pixel position @a pixel; false outside both rings.
bool ringRayDirection(const RingLayout& layout, const core::CameraFrame& frame, const glm::dvec2& pixel,
                      glm::vec3& direction);

}  // namespace ivis::render
