/// @file shadow.h
/// @brief Shadow rays sphere-traced through the level set (the paper's depth cue).
#pragma once

#include <ivis/core/triangle_mesh.h>
#include <ivis/render/distance_field.h>

#include <glm/vec3.hpp>

namespace ivis::render {

/// @brief The shadow rays' constants (the viewer's shader reads them too: app/viewer/shaders.cpp).
inline constexpr float kShadowSoftness = 8.0f;       ///< k of min(k d / t): larger is harder
inline constexpr float kShadowStartVoxels = 2.0f;    ///< the ray starts this many voxels off the surface
inline constexpr float kShadowHitVoxels = 0.5f;      ///< it meets the surface within this many voxels
inline constexpr float kShadowLeastStepVoxels = 0.5f;  ///< its smallest step
inline constexpr int kShadowMaxSteps = 512;          ///< its step cap
inline constexpr float kShadowMaxDistance = 6.0f;    ///< and how far it goes (normalised units)
inline constexpr float kShadowWallVoxels = 2.0f;     ///< on an open mesh, phi falling and rising within this many voxels is a wall

/// @brief Soft shadow factor in [0, 1] (1 = fully lit) toward a directional light: sphere traces
///        from @a point (offset two voxels along @a normal) along @a toLight by the distance d =
///        max(phi, distance to @a surfaceBox), darkening by the closest approach min(k d / t),
///        returning 0 when the ray meets the surface and ending when it leaves the box for good.
/// @param normal unit surface normal on the side facing the light
/// @param toLight unit direction from the surface to the light
/// @param surfaceBox a box containing the surface (hullBounds(mesh, 0, voxel)): beyond the field's
///        reach, where phi is clamped, its distance bounds the true distance from below
float shadowFactor(DistanceField::Sampler& sampler, const glm::vec3& point, const glm::vec3& normal,
                   const glm::vec3& toLight, const core::Bounds3& surfaceBox);

}  // namespace ivis::render
