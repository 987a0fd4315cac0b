/// @file quadratic_mirror.h
/// @brief The curved-mirror baseline: a quadratic height field behind the object whose normal is
///        used directly as the new ray direction (docs/method.md, "Baseline 2").
/// @note Eye space: camera at the origin looking down -z, x right, y up. The mirror is
///       z = zm + w1 x^2 + w2 y^2 + w3 xy + w4 x + w5 y with zm = -(eye-target distance) - distanceBehind.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/picture_extent.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace ivis::render {

/// @brief Quadratic mirror z = zm + w1 x^2 + w2 y^2 + w3 xy + w4 x + w5 y in eye space.
struct MirrorParams {
    /// w1..w5; the default is a shallow bowl: a flat mirror shows nothing and has zero gradient.
    std::array<float, 5> w{0.3f, 0.3f, 0.0f, 0.0f, 0.0f};
    float distanceBehind = 1.0f;  ///< mirror apex behind the object's centre (normalised units)
    int maxSteps = 300;           ///< sphere-tracing steps from the mirror
};

/// @brief Where a camera ray meets the mirror, and the mirror's unit normal there (world space).
struct MirrorHit {
    glm::vec3 point{};
    glm::vec3 normal{};
};

/// @brief Intersects the camera ray (world space) with the mirror: the smallest t > 0 root.
/// @return false when the ray does not meet the mirror in front of the camera
bool intersectMirror(const core::CameraFrame& frame, const core::CameraRay& ray, const MirrorParams& params,
                     MirrorHit& hit);

/// @brief How far the mirror's footprint reaches on the image plane (core::CameraFrame::imagePlane):
///        the camera rays that meet the mirror at a point inside the volume's box whose normal ray
///        hits the mesh of @a bvh, found on a 96^2 grid over the widest framed image
///        (widestFramedHalfHeight()) by a cheap test (the normal ray meets @a meshBounds) and then
///        on a 128^2 grid over those candidates by the exact one, plus one fine cell.
/// @param meshBounds bounds of the mesh of @a bvh
/// @return the footprint's extent (PictureExtent::empty() when empty), infinite on a side where it
///         reaches the edge of the widest framed image
PictureExtent mirrorFootprint(const core::Camera& camera, const MirrorParams& params, const core::TriangleBvh& bvh,
                           const core::Bounds3& meshBounds);

}  // namespace ivis::render
