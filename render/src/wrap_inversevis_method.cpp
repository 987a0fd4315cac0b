#include <ivis/render/wrap_inversevis_method.h>

#include <ivis/render/landed_extent.h>
#include <ivis/render/render_scene.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace ivis::render {
namespace {

/// A landing is stable when the rays of the ring's neighbouring pixels, their seeds this much
/// further in and out (about one pixel of a 1000-pixel picture of the object, normalised units),
/// land on a straight line through it, within WrapLaunch::stableShift.
constexpr float kNeighbourStep = 0.003f;

/// The wrap's ray parameters by default: a hull wider than the paper's 0.4, so that a thick
/// part's rings reach further round it, and rays that land a fifth as far from the surface as
/// the paper's, so that a ray skimming a ridge flies on past it (docs/optimisation.md, "A closer
/// landing").
CurvedRayParams wrapRayDefaults()
{
    CurvedRayParams params;
    params.hullOffset = 0.6f;
    params.landingVoxels = 0.1f;
    return params;
}

/// The local radius at the surface point closest to @a p, searched within @a bound; negative if none.
float localRadiusNear(const RenderScene& scene, const glm::vec3& p, double bound)
{
    int triangle = -1;
    const core::TrianglePoint closest = scene.bvh().closestPoint(glm::dvec3(p), bound, triangle);
    if (triangle < 0) return -1.0f;
    const auto& corners = scene.mesh().triangles[std::size_t(triangle)];
    const std::vector<float>& radii = scene.localRadii();
    return float(closest.barycentric.x) * radii[corners[0]] + float(closest.barycentric.y) * radii[corners[1]] +
           float(closest.barycentric.z) * radii[corners[2]];
}

}  // namespace

ParameterValues WrapInverseVisMethod::values() const
{
    ParameterValues values = curvedRayValues(rayParams());
    values["wrap_speed"] = {mLaunch.speed};
    values["wrap_tilt"] = {mLaunch.tilt};
    values["ring_scale"] = {mLaunch.ringScale};
    values["stable_shift"] = {mLaunch.stableShift};
    values["landing"] = {rayParams().landingVoxels};
    return values;
}

bool WrapInverseVisMethod::aim(const CurvedRayMap& rays, CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    const RenderScene& scene = rays.scene();
    const float distance = start.ring * rayParams().hullOffset;
    glm::vec3 gradient;
    sampler.phiAndGradient(start.seed, gradient);
    const float length = glm::length(gradient);
    const glm::vec3 outward = length > 0.0f ? gradient / length : glm::vec3(0.0f);
    // The radius where phi and its gradient lead down from the seed (as the viewer's shader finds
    // it): a search within two voxels of that foot, not within phi of the seed, which meets many
    // more triangles; where the foot lies off the surface, the search from the seed.
    const float voxel = scene.distance().voxelSize();
    float radius = localRadiusNear(scene, start.seed - distance * outward, 2.0 * voxel);
    if (radius < 0.0f) radius = localRadiusNear(scene, start.seed, 1.01 * distance + voxel);
    if (radius < 0.0f) {
        start.refusal = "no surface near its seed";
        return false;
    }
    const float width = std::min(mLaunch.ringScale * radius, rayParams().hullOffset);
    start.ring = distance / width;
    if (!(start.ring < 1.0f)) {
        start.refusal = "beyond its ring";
        return false;
    }

    // The launch at ring coordinate t: alpha = speed t (2 - t) along the view direction's part
    // tangential to the hull, tilted outward by tilt t.
    const glm::vec3 along = glm::normalize(start.velocityPerAlpha);
    auto alphaAt = [&](float t) { return mLaunch.speed * t * (2.0f - t); };
    auto directionAt = [&](float t) { return glm::normalize(along + mLaunch.tilt * t * outward); };
    auto launchAt = [&](float t) { return alphaAt(t) * directionAt(t); };
    start.velocityPerAlpha = directionAt(start.ring);
    start.alpha = alphaAt(start.ring);

    // Where rays fly smoothly, the landings of neighbouring pixels across the ring lie on a smooth
    // curve; where they fly chaotically, or part on either side of a tear, the rays launched from
    // a seed a pixel further in and out land far off it. Each probe moves the seed along the
    // outward gradient and the ring coordinate with it, as the neighbouring pixel's ray would.
    auto traceAt = [&](float shift) {
        return traceCurvedRay(sampler, start.seed + shift * outward, launchAt(start.ring + shift / width), rayParams(),
                              rays.epsilon());
    };
    const CurvedRayEnd here = traceAt(0.0f);
    const float step = std::min(kNeighbourStep, distance);  // the inner seed stays off the surface
    const CurvedRayEnd inner = here.landed ? traceAt(-step) : CurvedRayEnd{};
    const CurvedRayEnd outer = inner.landed ? traceAt(step) : CurvedRayEnd{};
    if (!outer.landed) {
        start.refusal = here.landed ? "a neighbouring pixel's ray does not land" : "its ray does not land";
        return false;
    }
    start.bend = glm::length(inner.position + outer.position - 2.0f * here.position);
    start.traced = here;  // the ray drawn: launchVelocity(start, 0) from the seed, as traced here
    const bool stable = start.bend <= mLaunch.stableShift;
    if (!stable) start.refusal = "its landing is unstable";
    return stable;
}

glm::vec3 WrapInverseVisMethod::launchVelocity(const CurvedRayStart& start, int /*launch*/) const
{
    return start.alpha * start.velocityPerAlpha;
}

PictureExtent WrapInverseVisMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return landedExtent(scene, camera, *this, CurvedRayMethod::pictureExtent(scene, camera));
}

const MethodInfo& wrapInverseVisMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "inversevis-wrap";
        i.help = "curved rays from the view ray's closest approach, unwrapping the back side outward from the "
                 "silhouette in rings as wide as each part is thick (beyond the paper)";
        const WrapLaunch defaults;
        i.parameters = {
            {"wrap_speed", "alpha at the ring's outer edge (alpha = speed * t (2 - t) across the ring coordinate t)", {defaults.speed}, 0.0f, kMaxAlpha},
            {"wrap_tilt", "outward tilt of the launch at the ring's outer edge", {defaults.tilt}, 0.0f, 4.0f},
            {"ring_scale", "ring width in local radii of the part it surrounds (at most hull_offset)", {defaults.ringScale}, 0.1f, 20.0f},
            {"stable_shift", "largest bend (normalised units) of the landings of a ray and of the rays seeded 0.003 further in and out across its ring (its neighbouring pixels'); rays that bend more fly chaotically or straddle a tear and are not drawn",
             {defaults.stableShift}, 0.0001f, 10.0f},
            {"landing", "a ray lands where phi falls below this many fine voxels (the paper's model: half a voxel)",
             {wrapRayDefaults().landingVoxels}, 0.01f, 1.0f, false, false, false, true}};
        for (const ParameterSpec& spec : curvedRaySpecs(wrapRayDefaults())) i.parameters.push_back(spec);
        i.readabilityParameter = "stable_shift";
        i.create = [](const ParameterValues& v) {
            WrapLaunch launch;
            launch.speed = v.at("wrap_speed")[0];
            launch.tilt = v.at("wrap_tilt")[0];
            launch.ringScale = v.at("ring_scale")[0];
            launch.stableShift = v.at("stable_shift")[0];
            CurvedRayParams ray = curvedRayParamsFrom(v);
            ray.landingVoxels = v.at("landing")[0];
            return std::make_shared<const WrapInverseVisMethod>(ray, launch);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
