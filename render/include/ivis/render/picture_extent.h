/// @file picture_extent.h
/// @brief How far a method's picture (the object and its indirect region) reaches from the image
///        centre, per image axis, independently of the field of view; what render/framing.h fits.
/// @note Image-plane units as core::CameraFrame::imagePlane(): at unit distance from the eye
///       (perspective) or world units (orthographic).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/triangle_mesh.h>

#include <glm/vec2.hpp>

namespace ivis::render {

/// @brief Free border that framing leaves on every side, in image half-heights (2.5% of the height).
inline constexpr double kFramingMargin = 0.05;
/// @brief Widest vertical field of view framing may choose (perspective).
inline constexpr double kMaxFramedFovYDeg = 150.0;
/// @brief Widest orthographic half height framing may choose: twice the volume box's half extent.
inline constexpr double kMaxFramedOrthoHalfHeight = 5.0;

/// @brief The reach of a picture from the image centre along the image's right (x) and up (y)
///        axes, both ways: a part that scales with the view and a part that stays a fixed share
///        of the image (the ring map's rings are as wide as a fraction of the image half-height).
/// @note A reach of +infinity cannot be framed (e.g. the eye inside the hull).
struct PictureExtent {
    glm::dvec2 imagePlane{0.0};  ///< largest |x| and |y| on the image plane
    glm::dvec2 fixed{0.0};       ///< added reach in image half-heights, whatever the field of view

    /// @brief The extent reaching as far as the farther of this and @a other on each axis.
    PictureExtent united(const PictureExtent& other) const;
};

/// @brief The widest image-plane half height framing may choose for @a camera's projection:
///        tan(kMaxFramedFovYDeg / 2) or kMaxFramedOrthoHalfHeight.
double widestFramedHalfHeight(const core::Camera& camera);

/// @brief The extent of the mesh grown by a ball of radius @a offset, seen from @a camera: for a
///        perspective camera, per axis the largest tan(angle to the vertex + asin(offset /
///        distance)) over the vertices, in the plane through the eye that holds the other axis.
/// @note Exact for the offset surface {distance to the mesh = offset} (the curved-ray hull): its
///       tangent planes through the eye touch the offset ball of a vertex of the convex hull, at a
///       point whose distance to the mesh is exactly @a offset.
/// @param offset the ball radius (normalised units, >= 0; 0: the mesh itself)
/// @return +infinity on an axis where a ball reaches the eye's side plane (the eye within the
///         offset of the mesh or the mesh beside or behind the eye)
PictureExtent offsetMeshExtent(const core::TriangleMesh& mesh, const core::Camera& camera, double offset);

}  // namespace ivis::render
