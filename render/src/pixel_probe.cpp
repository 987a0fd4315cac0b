#include <ivis/render/pixel_probe.h>

#include <ivis/core/sphere_lattice.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/screen_map.h>
#include <ivis/render/surface_point.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ivis::render {
namespace {

/// Eyes tried by facingView: about 3.2 degrees apart.
constexpr int kEyeCount = 4000;

}  // namespace

PixelProbe probePixel(const RenderScene& scene, const MethodPtr& method, const core::Camera& camera, int width,
                      int height, double x, double y, const AdaptiveSampling& sampling)
{
    const core::CameraFrame frame(camera, width, height);
    const ScreenMap map(scene, frame, method);
    DistanceField::Sampler sampler = scene.distance().sampler();
    PixelProbe probe;
    // The pixel's tile, as the renderer maps it (tileAt).
    const int px = std::clamp(int(std::floor(x)), 0, width - 1), py = std::clamp(int(std::floor(y)), 0, height - 1);
    const PixelTile tile = tileAt(py / kAdaptiveTileSize * tilesAcross(width) + px / kAdaptiveTileSize, width, height);
    std::vector<PixelMapping> mappings(std::size_t(tile.width) * tile.height);
    TileCounts counts;
    map.mapTile(tile, {x - px, y - py}, sampling, sampler, mappings.data(), counts);
    probe.mapping = mappings[std::size_t(py - tile.y0) * tile.width + (px - tile.x0)];
    probe.scalar = scalarAt(scene.field(), probe.mapping.point);
    if (probe.mapping.point.valid()) {
        const glm::vec3 normal = triangleNormal(scene.mesh(), probe.mapping.point.triangle);
        probe.facing = glm::dot(normal, probe.mapping.arrival) > 0.0f ? -normal : normal;
        if (probe.mapping.region == Region::Indirect && !method->indirectRaysArriveFromOutside())
            probe.facing = -probe.facing;
    }
    const CurvedRayMap* rays = map.curvedRays();
    if (!rays || probe.mapping.region == Region::Direct) return probe;
    CurvedRayStart start;
    // No launch to tell where the view ray hits the surface after all or does not come within the hull.
    if (!rays->start(x, y, sampler, start) && (start.refusal == Refusal::None || start.refusal == Refusal::NoSeed))
        return probe;
    const CurvedRayMethod& curved = *method->curved();
    ProbedLaunch& launch = probe.launch.emplace();
    launch.seed = start.seed;
    if (start.ring) launch.ring = start.ring->coordinate;
    const float speed = glm::length(curved.launchVelocity(start, 0));
    if (speed > 0.0f || start.refusal == Refusal::None) launch.speed = speed;  // a seed refused before its launch has none
    launch.bend = start.bend;
    // A ray the method launched but that did not land shows the background too.
    launch.refusal = start.refusal != Refusal::None                ? describe(start.refusal)
                     : probe.mapping.region == Region::Indirect ? nullptr
                                                                 : describe(Refusal::DoesNotLand);
    return probe;
}

bool seenDirectly(const core::TriangleBvh& bvh, const glm::dvec3& eye, const glm::vec3& point, int triangle)
{
    const glm::vec3 origin(eye);
    const glm::vec3 line = point - origin;
    const float length = glm::length(line);
    if (!(length > 0.0f)) return false;
    const core::RayHit hit = bvh.intersect(origin, line / length, 0.0f, 2.0f * length);
    return hit.hit() && (hit.triangle == triangle || std::abs(hit.t - length) <= 1e-4f * length);
}

std::optional<glm::dvec2> facingView(const core::TriangleBvh& bvh, const glm::vec3& point, int triangle,
                                     const glm::vec3& facing, double radius)
{
    std::optional<glm::dvec2> best;
    double bestCos = 0.0;  // only eyes that the side faces
    for (int i = 0; i < kEyeCount; ++i) {
        // A Fibonacci sphere, even in area; its eyes nearest the poles lie 1.3 degrees off the up
        // axis, to which the camera's up vector would be parallel.
        core::Camera view;
        view.eye = radius * core::fibonacciDirection(i, kEyeCount);
        const glm::dvec3 toEye = view.eye - glm::dvec3(point);
        const double cosine = glm::dot(glm::normalize(toEye), glm::dvec3(facing));
        if (cosine <= bestCos || !seenDirectly(bvh, view.eye, point, triangle)) continue;
        bestCos = cosine;
        best = view.angles();
    }
    return best;
}

}  // namespace ivis::render
