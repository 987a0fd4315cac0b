/// @file inversevis_wrap_method.h
/// @brief The `inversevis-wrap` method (beyond the paper): the back side unwraps outward from the
///        silhouette. A ring pixel's curved ray starts where its view ray passes closest to the
///        surface; the ring around each part is as wide as the part is thick; the further out
///        across its ring the pixel lies, the faster and the more steeply outward the ray is
///        launched, so it falls further round the back. A ray whose landing is not stable under
///        a small change of its launch would tear the picture and is not drawn.
#pragma once

#include <ivis/render/curved_ray_method.h>

#include <glm/geometric.hpp>

namespace ivis::render {

/// @brief The stability rule's probes are seeded this far (normalised units) further in and out
///        across the ring: about one pixel of a 1000-pixel picture of the object (the viewer's
///        shader reads it too).
inline constexpr float kWrapProbeStep = 0.003f;

/// @brief Launch of the wrap rays across the ring coordinate t in [0, 1).
struct WrapLaunch {
    float ringScale = 12.0f;  ///< ring width in local radii of the part it surrounds (at most the hull offset)
    float speed = 2.5f;       ///< alpha = speed * t (2 - t): fastest, and changing least, at the outer edge
    float tilt = 0.5f;        ///< launch direction: view direction + tilt * t * grad phi (normalised)
    float stableShift = 0.1f;  ///< largest |P(inner) + P(outer) - 2 P| over the neighbouring pixels' rays (else not drawn)

    /// @brief The launch speed at ring coordinate @a t: speed t (2 - t).
    float alphaAt(float t) const { return speed * t * (2.0f - t); }
    /// @brief The launch direction at ring coordinate @a t: @a along (the view direction's part
    ///        tangential to the hull) tilted outward by tilt t along @a outward, normalised.
    glm::vec3 directionAt(const glm::vec3& along, const glm::vec3& outward, float t) const
    {
        return glm::normalize(along + tilt * t * outward);
    }
};

/// @brief The local radius of each vertex of @a scene's mesh (vertexLocalRadii capped at the
///        normalised half-extent 1), which sizes the rings: made once per scene (RenderScene::derived).
const std::vector<float>& wrapLocalRadii(const RenderScene& scene);

/// @brief Description of `inversevis-wrap`: wrap_speed, wrap_tilt, ring_scale, stable_shift (the
///        readable rule's parameter), landing, hull_offset, step, max_steps; none is optimised by the ascent
///        (each ray's speed and stability are set when it is aimed, docs/optimisation.md).
const MethodInfo& inverseVisWrapMethodInfo();

/// @brief Curved rays from the closest approach, launched by WrapLaunch.
class InverseVisWrapMethod final : public CurvedRayMethod {
public:
    /// @brief The method with rays @a ray launched by @a launch.
    InverseVisWrapMethod(const CurvedRayParams& ray, const WrapLaunch& launch) : CurvedRayMethod(ray), mLaunch(launch) {}
    const MethodInfo& info() const override { return inverseVisWrapMethodInfo(); }
    ParameterValues values() const override;
    /// @brief Rays start at the view ray's closest approach to the surface, not the hull exit.
    SeedRule seedRule() const override { return SeedRule::ClosestApproach; }
    /// @brief Sets the ring position from the local radius, the launch direction and alpha; false
    ///        beyond the ring or with no surface near the seed.
    bool aim(const CurvedRayMap& rays, CurvedRayStart& start, DistanceField::Sampler& sampler) const override;
    /// @brief The rays seeded a neighbouring pixel further in and out across the ring (along the
    ///        outward normal), the ring coordinate moving with them.
    int stabilityProbes(const CurvedRayStart& start, CurvedRayStart* probes) const override;
    /// @brief The stability rule: the ray and both probes land, their landings bending by at most
    ///        stable_shift.
    bool isStable(CurvedRayStart& start, const CurvedRayEnd& own, const CurvedRayEnd* probes) const override;
    /// @brief The speed and direction aim() set for the ray.
    glm::vec3 launchVelocity(const CurvedRayStart& start, int launch) const override;
    /// @brief stable_shift between probes a neighbouring pixel (of a 1000-pixel picture) apart.
    std::optional<StabilityScale> stabilityScale() const override;
    /// @brief The object and the pixels whose rays land (landedExtent within the hull): the rings
    ///        are narrower than the hull round thin parts and where their outer rays are not drawn.
    PictureExtent pictureExtent(const RenderScene& scene, const core::Camera& camera) const override;
    /// @brief The hull offset and 0.4 beyond it: the fast outer rays of a ring fly out before they
    ///        fall back (docs/decisions/wrap-rings.md).
    float reachNeeded() const override { return rayParams().hullOffset + 0.4f; }
    /// @brief The launch rule.
    const WrapLaunch& launch() const { return mLaunch; }

private:
    WrapLaunch mLaunch;
};

}  // namespace ivis::render
