/// @file picture_extent.h
/// @brief Where a method's picture (the object and its indirect region) reaches on the image
///        plane, per image axis and side, independently of the field of view; what
///        render/framing.h fits.
/// @note Image-plane units as core::CameraFrame::imagePlane(): at unit distance from the eye
///       (perspective) or world units (orthographic).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/clustered_vertices.h>

#include <glm/vec2.hpp>

namespace ivis::render {

/// @brief Free border that framing leaves on every side, in image half-heights (2.5% of the height).
inline constexpr double kFramingMargin = 0.05;
/// @brief Widest vertical field of view framing may choose (perspective).
inline constexpr double kMaxFramedFovYDeg = 150.0;
/// @brief Widest orthographic half height framing may choose: twice the volume box's half extent.
inline constexpr double kMaxFramedOrthoHalfHeight = 5.0;

/// @brief The reach of a picture along the image's right (x) and up (y) axes, on either side of
///        the view axis: a part that scales with the view (from lo to hi on the image plane) and a
///        part that stays a fixed share of the image (the ring map's rings are as wide as a fraction
///        of the image half-height), added on both sides.
/// @note An infinite reach cannot be framed (e.g. the eye inside the hull). lo > hi on an axis:
///       nothing there (empty()).
struct PictureExtent {
    glm::dvec2 lo{0.0};     ///< least x and y on the image plane
    glm::dvec2 hi{0.0};     ///< greatest x and y on the image plane
    glm::dvec2 fixed{0.0};  ///< added reach in image half-heights on every side, whatever the field of view

    /// @brief An extent holding nothing: united() with it changes nothing.
    static PictureExtent empty();
    /// @brief The extent reaching as far as the farther of this and @a other on each side.
    PictureExtent united(const PictureExtent& other) const;
};

/// @brief The widest image-plane half height framing may choose for @a camera's projection:
///        tan(kMaxFramedFovYDeg / 2) or kMaxFramedOrthoHalfHeight.
double widestFramedHalfHeight(const core::Camera& camera);

/// @brief The extent of the mesh grown by a ball of radius @a offset, seen from @a camera: for a
///        perspective camera, per axis and side the farthest tan(angle to the vertex +- asin(offset
///        / distance)) over the vertices, in the plane through the eye that holds the other axis.
/// @note Exact for the offset surface {distance to the mesh = offset} (the curved-ray hull): its
///       tangent planes through the eye touch the offset ball of a vertex of the convex hull, at a
///       point whose distance to the mesh is exactly @a offset.
/// @note The same whatever the clusters: a cluster's vertices are skipped only where the ball that
///       holds them, grown by the offset, lies wholly in front of the eye and reaches less far
///       than some vertex's ball.
/// @param vertices the mesh's vertices (RenderScene::vertices())
/// @param offset the ball radius (normalised units, >= 0; 0: the mesh itself)
/// @return an infinite reach on a side where a ball reaches the eye's side plane (the eye within
///         the offset of the mesh or the mesh beside or behind the eye)
PictureExtent offsetMeshExtent(const core::ClusteredVertices& vertices, const core::Camera& camera, double offset);

}  // namespace ivis::render
