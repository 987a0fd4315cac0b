/// @file pixel_probe.h
/// @brief What a reader asks of one pixel of a picture: the surface point it shows (through its
///        view ray or the method's indirect ray) and the scalar there, and a view that shows that
///        point directly, so that a hot spot seen in the rings can be found on the object.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/triangle_bvh.h>
#include <ivis/render/adaptive_sampling.h>
#include <ivis/render/method.h>
#include <ivis/render/pixel_mapping.h>
#include <ivis/render/render_scene.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace ivis::render {

/// @brief How a curved-ray method starts a pixel's ray, and whether it draws it.
struct ProbedLaunch {
    glm::vec3 seed{0.0f};      ///< where the ray starts (normalised units)
    std::optional<float> ring;  ///< where across its ring the seed lies, 0 at the silhouette to 1 at the
                                ///< ring's outer edge (closest-approach seeds only: inversevis-wrap)
    std::optional<float> speed;  ///< the first launch velocity's length (inversevis-wrap: its alpha); none
                                 ///< for a seed refused before its launch
    float bend = 0.0f;         ///< the stability rule's measure (inversevis-wrap; 0 where not measured)
    const char* refusal = nullptr;  ///< why the method draws no ray here (CurvedRayStart::refusal); null: drawn
};

/// @brief What one pixel shows.
struct PixelProbe {
    PixelMapping mapping;  ///< the region and the surface point (normalised units), as the renderer maps the pixel
    float scalar = 0.0f;   ///< the shown scalar at the point (scalarAt: NaN for none)
    /// The unit normal of the side of the surface the pixel shows: the point's triangle normal,
    /// turned against the direction the point is seen along; for an indirect pixel of a method whose
    /// rays start inside the object (the ring map: Method::indirectRaysArriveFromOutside), the wall's
    /// other side, which a view from outside sees (zero for the background).
    glm::vec3 facing{0.0f};
    /// A curved-ray method's ray of a pixel whose view ray misses the surface and meets the hull.
    std::optional<ProbedLaunch> launch;
};

/// @brief What continuous pixel position (x, y) (pixel centres at +0.5, from the top left, inside
///        the picture) of a @a width x @a height picture of @a method from @a camera shows: as the
///        renderer maps it under @a sampling (its pixel's tile sampled as the renderer samples it).
PixelProbe probePixel(const RenderScene& scene, const MethodPtr& method, const core::Camera& camera, int width,
                      int height, double x, double y, const AdaptiveSampling& sampling = {});

/// @brief True when the straight line from @a eye to @a point meets the surface first at @a point
///        (within 10^-4 of the line's length, or on @a triangle).
bool seenDirectly(const core::TriangleBvh& bvh, const glm::dvec3& eye, const glm::vec3& point, int triangle);

/// @brief The polar and azimuth angles (degrees, Camera::fromAngles) of an eye on the sphere of
///        @a radius around the origin that sees @a point of @a triangle directly and most nearly
///        head-on: of 4,000 eyes spread evenly over the sphere (theta 1.3 to 178.7 degrees), the one
///        whose line of sight meets the surface first at the point, on its side @a facing, at the
///        smallest angle to @a facing; nullopt when no eye sees that side of the point.
std::optional<glm::dvec2> facingView(const core::TriangleBvh& bvh, const glm::vec3& point, int triangle,
                                     const glm::vec3& facing, double radius = core::kCameraDistance);

}  // namespace ivis::render
