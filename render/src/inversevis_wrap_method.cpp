#include <ivis/render/inversevis_wrap_method.h>

#include <ivis/core/number_text.h>
#include <ivis/render/landed_extent.h>
#include <ivis/render/local_radius.h>
#include <ivis/render/render_scene.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace ivis::render {
namespace {

/// The wrap's ray parameters by default: a hull wider than the paper's 0.4, so that a thick
/// part's rings reach further round it, and rays that land a fifth as far from the surface as
/// the paper's, so that a ray skimming a ridge flies on past it
/// (docs/decisions/wrap-flight-and-landing.md).
CurvedRayParams wrapRayDefaults()
{
    CurvedRayParams params;
    params.hullOffset = 0.6f;
    params.landingVoxels = 0.1f;
    return params;
}

/// The local radius (@a radii per vertex) at the surface point closest to @a p, searched within
/// @a bound; negative if none.
float localRadiusNear(const RenderScene& scene, const std::vector<float>& radii, const glm::vec3& p, double bound)
{
    int triangle = -1;
    const core::TrianglePoint closest = scene.bvh().closestPoint(glm::dvec3(p), bound, triangle);
    if (triangle < 0) return -1.0f;
    const auto& corners = scene.mesh().triangles[std::size_t(triangle)];
    return float(closest.barycentric.x) * radii[corners[0]] + float(closest.barycentric.y) * radii[corners[1]] +
           float(closest.barycentric.z) * radii[corners[2]];
}

}  // namespace

const std::vector<float>& wrapLocalRadii(const RenderScene& scene)
{
    return scene.derived<std::vector<float>>("inversevis-wrap local radii", [](const RenderScene& s) {
        return vertexLocalRadii(s.mesh(), s.bvh(), s.normals(), 1.0f);
    });
}

ParameterValues InverseVisWrapMethod::values() const
{
    ParameterValues values = curvedRayValues(rayParams());
    values["wrap_speed"] = {mLaunch.speed};
    values["wrap_tilt"] = {mLaunch.tilt};
    values["ring_scale"] = {mLaunch.ringScale};
    values["stable_shift"] = {mLaunch.stableShift};
    values["landing"] = {rayParams().landingVoxels};
    return values;
}

namespace {

/// The unit outward normal of the hull at a start's seed (zero where the gradient vanishes).
glm::vec3 outwardAt(const CurvedRayStart& start)
{
    const float length = glm::length(start.gradient);
    return length > 0.0f ? start.gradient / length : glm::vec3(0.0f);
}

}  // namespace

bool InverseVisWrapMethod::aim(const CurvedRayMap& rays, CurvedRayStart& start, DistanceField::Sampler& /*sampler*/) const
{
    const RenderScene& scene = rays.scene();
    const float distance = start.seedDistance;
    const glm::vec3 outward = outwardAt(start);
    // The radius where phi and its gradient lead down from the seed (as the viewer's shader finds
    // it): a search within two voxels of that foot, not within phi of the seed, which meets many
    // more triangles; where the foot lies off the surface, the search from the seed.
    const float voxel = scene.distance().voxelSize();
    const std::vector<float>& radii = wrapLocalRadii(scene);
    float radius = localRadiusNear(scene, radii, start.seed - distance * outward, 2.0 * voxel);
    if (radius < 0.0f) radius = localRadiusNear(scene, radii, start.seed, 1.01 * distance + voxel);
    if (radius < 0.0f) {
        start.refusal = Refusal::NoSurfaceNearSeed;
        return false;
    }
    RingPosition& ring = start.ring.emplace();
    ring.width = std::min(mLaunch.ringScale * radius, rayParams().hullOffset);
    ring.coordinate = distance / ring.width;
    if (!(ring.coordinate < 1.0f)) {
        start.refusal = Refusal::BeyondRing;
        return false;
    }
    const glm::vec3 along = glm::normalize(start.tangent);
    start.launchDirection = mLaunch.directionAt(along, outward, ring.coordinate);
    start.alpha = mLaunch.alphaAt(ring.coordinate);
    return true;
}

int InverseVisWrapMethod::stabilityProbes(const CurvedRayStart& start, CurvedRayStart* probes) const
{
    // Where rays fly smoothly, the landings of neighbouring pixels across the ring lie on a smooth
    // curve; where they fly chaotically, or part on either side of a tear, the rays launched from
    // a seed a pixel further in and out land far off it. Each probe moves the seed along the
    // outward gradient and the ring coordinate with it, as the neighbouring pixel's ray would.
    const glm::vec3 outward = outwardAt(start);
    const glm::vec3 along = glm::normalize(start.tangent);
    const float step = std::min(kWrapProbeStep, start.seedDistance);  // the inner seed stays off the surface
    const RingPosition& ring = *start.ring;
    for (int k = 0; k < 2; ++k) {
        const float shift = k == 0 ? -step : step;
        const float t = ring.coordinate + shift / ring.width;
        CurvedRayStart& probe = probes[k];
        probe.seed = start.seed + shift * outward;
        probe.alpha = mLaunch.alphaAt(t);
        probe.launchDirection = mLaunch.directionAt(along, outward, t);
    }
    return 2;
}

bool InverseVisWrapMethod::isStable(CurvedRayStart& start, const CurvedRayEnd& own, const CurvedRayEnd* probes) const
{
    if (!own.landed || !probes[0].landed || !probes[1].landed) {
        start.refusal = own.landed ? Refusal::NeighbourDoesNotLand : Refusal::DoesNotLand;
        return false;
    }
    start.bend = glm::length(probes[0].position + probes[1].position - 2.0f * own.position);
    if (start.bend <= mLaunch.stableShift) return true;
    start.refusal = Refusal::Unstable;
    return false;
}

std::optional<StabilityScale> InverseVisWrapMethod::stabilityScale() const
{
    return StabilityScale{mLaunch.stableShift, kWrapProbeStep};
}

glm::vec3 InverseVisWrapMethod::launchVelocity(const CurvedRayStart& start, int /*launch*/) const
{
    return start.alpha * start.launchDirection;
}

PictureExtent InverseVisWrapMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return landedExtent(scene, camera, *this, CurvedRayMethod::pictureExtent(scene, camera));
}

const MethodInfo& inverseVisWrapMethodInfo()
{
    static const MethodInfo info = [] {
        MethodInfo i;
        i.name = "inversevis-wrap";
        i.help = "curved rays from the view ray's closest approach, unwrapping the back side outward from the "
                 "silhouette in rings as wide as each part is thick (beyond the paper)";
        const WrapLaunch defaults;
        const std::string probeStep = core::shortNumber(kWrapProbeStep);
        i.parameters = {
            {"wrap_speed", "alpha at the ring's outer edge (alpha = speed * t (2 - t) across the ring coordinate t)", {defaults.speed}, 0.0f, kMaxAlpha},
            {"wrap_tilt", "outward tilt of the launch at the ring's outer edge", {defaults.tilt}, 0.0f, 4.0f},
            {"ring_scale", "ring width in local radii of the part it surrounds (at most hull_offset)", {defaults.ringScale}, 0.1f, 20.0f},
            {"stable_shift", "largest bend (normalised units) of the landings of a ray and of the rays seeded " + probeStep +
                                 " further in and out across its ring (its neighbouring pixels'); rays that bend more fly "
                                 "chaotically or straddle a tear and are not drawn",
             {defaults.stableShift}, 0.0001f, 10.0f},
            ParameterSpec{"landing", "a ray lands where phi falls below this many fine voxels (the paper's model: half a voxel)",
                          {wrapRayDefaults().landingVoxels}, 0.01f, 1.0f}
                .ofTheTracer()};
        for (const ParameterSpec& spec : curvedRaySpecs(wrapRayDefaults())) i.parameters.push_back(spec);
        i.readableRuleParameter = "stable_shift";
        i.vertexArrays = {[](const RenderScene& scene) { return wrapLocalRadii(scene); }};
        i.create = [](const ParameterValues& v) {
            WrapLaunch launch;
            launch.speed = v.at("wrap_speed")[0];
            launch.tilt = v.at("wrap_tilt")[0];
            launch.ringScale = v.at("ring_scale")[0];
            launch.stableShift = v.at("stable_shift")[0];
            CurvedRayParams ray = curvedRayParamsFrom(v);
            ray.landingVoxels = v.at("landing")[0];
            return std::make_shared<const InverseVisWrapMethod>(ray, launch);
        };
        return i;
    }();
    return info;
}

}  // namespace ivis::render
