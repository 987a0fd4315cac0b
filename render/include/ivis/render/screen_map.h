/// @file screen_map.h
/// @brief The map P: I -> S of METHOD.md: for a pixel position, the surface point it shows, by
///        a straight view ray (I+) or by the chosen method's indirect ray (I-).
/// @warning map() is const and thread-safe given one DistanceField::Sampler per thread.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/render/method.h>
#include <ivis/render/neugebauer_map.h>
#include <ivis/render/render_scene.h>
#include <ivis/render/surface_point.h>

#include <cstdint>

namespace ivis::render {

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

/// @brief Start of one pixel's curved ray (InverseVis and its adaptive variant).
struct CurvedRayStart {
    glm::vec3 seed{};              ///< farthest crossing of the view ray with the hull
    glm::vec3 velocityPerAlpha{};  ///< v0 / alpha: the view direction's part tangential to the hull
    float alignment = 0.0f;        ///< c = r . grad phi / |grad phi| at the seed
};

/// @brief P for one camera, image size and method.
class ScreenMap {
public:
    /// @brief Prepares the method's per-view state (ring radii from the silhouette).
    ScreenMap(const RenderScene& scene, const core::CameraFrame& frame, const MethodParams& params);

    /// @brief The surface point shown at continuous pixel position (x, y).
    PixelMapping map(double x, double y, DistanceField::Sampler& sampler) const;

    /// @brief The direct part of map(): the surface point the view ray of (x, y) hits, or background.
    PixelMapping directHit(double x, double y) const;
    /// @brief The indirect part of map(), for a pixel whose view ray misses the surface: what the
    ///        method's indirect ray shows there.
    PixelMapping indirect(double x, double y, DistanceField::Sampler& sampler) const;

    /// @brief Start of the curved ray of pixel position (x, y): the hull seed and the initial
    ///        velocity per unit alpha (v0 = alpha * velocityPerAlpha).
    /// @return false when the view ray hits the surface or misses the hull
    bool curvedRayStart(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const;

    /// @brief The alpha of a curved ray: the global alpha, or the adaptive profile's alpha(c).
    float alphaOf(const CurvedRayStart& start) const;

    /// @brief Traces the curved ray of @a start with alphaOf(start); the adaptive method relaunches a
    ///        ray that does not land with half its alpha, up to AlphaProfile::retries times.
    /// @param[out] alpha the alpha of the last launch
    CurvedRayEnd traceFrom(const CurvedRayStart& start, DistanceField::Sampler& sampler, float& alpha) const;

    /// @brief The surface point a curved ray from @a start lands on (a launched miss if none).
    PixelMapping curvedRay(const CurvedRayStart& start, DistanceField::Sampler& sampler) const;

    /// @brief Indirect mapping for a point that reached the surface (phi < eps): its exact closest
    ///        surface point (BVH search bounded by the triangle stored at its nearest fine voxel).
    PixelMapping landedAt(const glm::vec3& p, const glm::vec3& arrival, int steps,
                          DistanceField::Sampler& sampler) const;

    /// @brief The ring layout (meaningful for Method::Neugebauer).
    const RingLayout& rings() const { return mRings; }
    const MethodParams& params() const { return mParams; }

private:
    PixelMapping inverseVis(const core::CameraRay& ray, DistanceField::Sampler& sampler) const;
    bool seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, CurvedRayStart& start) const;
    PixelMapping mirror(const core::CameraRay& ray, DistanceField::Sampler& sampler) const;
    PixelMapping ring(const glm::dvec2& pixel) const;
    const RenderScene& mScene;
    core::CameraFrame mFrame;
    MethodParams mParams;
    RingLayout mRings;
    core::Bounds3 mHullBox;
    float mEpsilon;
};

}  // namespace ivis::render
