#include <ivis/render/wrap_inversevis_method.h>

#include <ivis/render/landed_extent.h>
#include <ivis/render/render_scene.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace ivis::render {
namespace {

/// A landing is stable when the launches this much slower and faster land on a straight line
/// through it, within WrapLaunch::stableShift.
constexpr float kSpeedProbe = 0.01f;

/// The wrap's ray parameters by default: a hull wider than the paper's 0.4, so that a thick
/// part's rings reach further round it.
CurvedRayParams wrapRayDefaults()
{
    CurvedRayParams params;
    params.hullOffset = 0.6f;
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
    if (radius < 0.0f) return false;
    start.ring = distance / std::min(mLaunch.ringScale * radius, rayParams().hullOffset);
    if (!(start.ring < 1.0f)) return false;

    start.velocityPerAlpha = glm::normalize(glm::normalize(start.velocityPerAlpha) + mLaunch.tilt * start.ring * outward);
    start.alpha = mLaunch.speed * start.ring * (2.0f - start.ring);

    // Where rays fly smoothly, the landing moves along a smooth curve as the launch speed changes,
    // however fast; where they fly chaotically, a slightly slower and a slightly faster launch
    // land far off that curve.
    auto traceAt = [&](float alpha) {
        return traceCurvedRay(sampler, start.seed, alpha * start.velocityPerAlpha, rayParams(), rays.epsilon());
    };
    const CurvedRayEnd here = traceAt(start.alpha);
    if (!here.landed) return false;
    const CurvedRayEnd slower = traceAt(start.alpha - kSpeedProbe);
    if (!slower.landed) return false;
    const CurvedRayEnd faster = traceAt(start.alpha + kSpeedProbe);
    if (!faster.landed) return false;
    start.bend = glm::length(slower.position + faster.position - 2.0f * here.position);
    start.traced = here;  // the ray drawn: launchVelocity(start, 0) from the seed, as traced here
    return start.bend <= mLaunch.stableShift;
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
            {"stable_shift", "largest bend (normalised units) of the landings of alpha - 0.01, alpha, alpha + 0.01; rays that bend more fly chaotically and are not drawn",
             {defaults.stableShift}, 0.0001f, 10.0f}};
        for (const ParameterSpec& spec : curvedRaySpecs(wrapRayDefaults())) i.parameters.push_back(spec);
        i.readabilityParameter = "stable_shift";
        i.create = [](const ParameterValues& v) {
            WrapLaunch launch;
            launch.speed = v.at("wrap_speed")[0];
            launch.tilt = v.at("wrap_tilt")[0];
            launch.ringScale = v.at("ring_scale")[0];
            launch.stableShift = v.at("stable_shift")[0];
            return std::make_shared<const WrapInverseVisMethod>(curvedRayParamsFrom(v), launch);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
