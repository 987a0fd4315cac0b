/// @file pixel_mapping.h
/// @brief What one pixel sample shows: its region of the image domain (I0, I+, I-) and the
///        surface point P(i) of docs/method.md, with how the point was reached.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/distance_field.h>
#include <ivis/render/surface_point.h>

#include <glm/vec3.hpp>

#include <cstdint>

namespace ivis::render {

class RenderScene;

/// @brief Partition of the image domain: I0, I+, I-.
enum class Region : std::uint8_t { Background = 0, Direct = 1, Indirect = 2 };

/// @brief What one pixel sample shows.
struct PixelMapping {
    Region region = Region::Background;
    SurfacePoint point;     ///< valid for Direct and Indirect
    float depth = 0.0f;     ///< distance from the eye to the point shown (0 for background)
    int steps = 0;          ///< integration / sphere-tracing steps of the indirect ray
    bool launched = false;  ///< an indirect ray was launched for this sample
    glm::vec3 arrival{};    ///< unit direction along which the point is seen (toward the surface)
};

/// @brief An indirect ray that was launched and did not land after @a steps steps.
PixelMapping launchedMiss(int steps);

/// @brief Indirect mapping for a point that reached the surface (phi < eps): its exact closest
///        surface point (BVH search bounded by the triangle stored at its nearest fine voxel).
/// @param arrival direction of travel at the landing (normalised here; the view direction if zero)
PixelMapping landedAt(const RenderScene& scene, const core::CameraFrame& frame, const glm::vec3& p,
                      const glm::vec3& arrival, int steps, DistanceField::Sampler& sampler);

/// @brief Indirect mapping of the first surface hit of a straight ray from @a origin along
///        @a direction (a launched miss when it hits nothing).
PixelMapping straightHit(const RenderScene& scene, const core::CameraFrame& frame, const glm::vec3& origin,
                         const glm::vec3& direction);

}  // namespace ivis::render
