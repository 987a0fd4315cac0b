#include <ivis/render/screen_map.h>

#include <ivis/render/curved_ray.h>
#include <ivis/render/quadratic_mirror.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace ivis::render {

ScreenMap::ScreenMap(const RenderScene& scene, const core::CameraFrame& frame, const MethodParams& params)
    : mScene(scene),
      mFrame(frame),
      mParams(params),
      mHullBox(hullBounds(scene.mesh(), params.curved.hullOffset, scene.distance().voxelSize())),
      mEpsilon(landingEpsilon(params.curved, scene.distance()))
{
    if (params.method == Method::Neugebauer) mRings = layoutRings(frame, scene.mesh(), params.ring);
}

PixelMapping ScreenMap::directHit(double x, double y) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    const glm::vec3 direction(ray.direction);
    const core::FaceFilter filter = mParams.method == Method::Backfaces ? core::FaceFilter::BackOnly : core::FaceFilter::Any;
    const core::RayHit hit = mScene.bvh().intersect(glm::vec3(ray.origin), direction, 0.0f, 1e30f, filter);
    if (!hit.hit()) return {};
    PixelMapping direct;
    direct.region = Region::Direct;
    direct.point = pointOnTriangle(mScene.mesh(), hit.triangle, hit.barycentric);
    direct.depth = glm::length(direct.point.position - glm::vec3(mFrame.camera().eye));
    direct.arrival = direction;
    return direct;
}

PixelMapping ScreenMap::map(double x, double y, DistanceField::Sampler& sampler) const
{
    const PixelMapping direct = directHit(x, y);
    return direct.region == Region::Direct ? direct : indirect(x, y, sampler);
}

PixelMapping ScreenMap::indirect(double x, double y, DistanceField::Sampler& sampler) const
{
    switch (mParams.method) {
    case Method::InverseVis:
    case Method::InverseVisAdaptive: return inverseVis(mFrame.ray(x, y), sampler);
    case Method::Mirror: return mirror(mFrame.ray(x, y), sampler);
    case Method::Neugebauer: return ring({x, y});
    case Method::Front:
    case Method::Backfaces: break;
    }
    return {};
}

PixelMapping ScreenMap::landedAt(const glm::vec3& p, const glm::vec3& arrival, int steps,
                                 DistanceField::Sampler& sampler) const
{
    PixelMapping result;
    result.launched = true;
    result.steps = steps;
    // The triangle stored at the nearest voxel is closest to that voxel's centre; its distance to p
    // bounds a BVH search that returns the exact closest surface point of p.
    const int stored = sampler.nearestTriangle(p);
    const double bound = stored >= 0 ? glm::length(projectOntoTriangle(mScene.mesh(), stored, p).position - p)
                                     : std::numeric_limits<double>::infinity();
    int triangle = -1;
    const core::TrianglePoint closest = mScene.bvh().closestPoint(glm::dvec3(p), bound, triangle);
    if (triangle < 0) return result;
    result.region = Region::Indirect;
    result.point = {triangle, glm::vec3(closest.barycentric), glm::vec3(closest.point)};
    result.depth = glm::length(result.point.position - glm::vec3(mFrame.camera().eye));
    const float length = glm::length(arrival);
    result.arrival = length > 0.0f ? arrival / length : glm::vec3(mFrame.forward());
    return result;
}

bool ScreenMap::seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    const glm::vec3 direction(ray.direction);
    if (!findHullExit(sampler, glm::vec3(ray.origin), direction, mParams.curved.hullOffset, mHullBox, start.seed))
        return false;
    glm::vec3 gradient;
    sampler.phiAndGradient(start.seed, gradient);
    start.velocityPerAlpha = initialVelocity(gradient, direction, 1.0f);
    const float length = glm::length(gradient);
    start.alignment = length > 0.0f ? glm::dot(direction, gradient) / length : 0.0f;
    return true;
}

bool ScreenMap::curvedRayStart(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    if (mScene.bvh().intersect(glm::vec3(ray.origin), glm::vec3(ray.direction)).hit()) return false;
    return seedFromRay(ray, sampler, start);
}

float ScreenMap::alphaOf(const CurvedRayStart& start) const
{
    return mParams.method == Method::InverseVisAdaptive ? mParams.profile.at(start.alignment) : mParams.curved.alpha;
}

PixelMapping ScreenMap::inverseVis(const core::CameraRay& ray, DistanceField::Sampler& sampler) const
{
    CurvedRayStart start;
    if (!seedFromRay(ray, sampler, start)) return {};
    return curvedRay(start, sampler);
}

CurvedRayEnd ScreenMap::traceFrom(const CurvedRayStart& start, DistanceField::Sampler& sampler, float& alpha) const
{
    alpha = alphaOf(start);
    const int retries = mParams.method == Method::InverseVisAdaptive ? mParams.profile.retries : 0;
    for (int attempt = 0;; ++attempt) {
        const CurvedRayEnd end =
            traceCurvedRay(sampler, start.seed, alpha * start.velocityPerAlpha, mParams.curved, mEpsilon);
        if (end.landed || attempt == retries || alpha == 0.0f) return end;
        alpha *= 0.5f;
    }
}

PixelMapping ScreenMap::curvedRay(const CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    float alpha;
    const CurvedRayEnd end = traceFrom(start, sampler, alpha);
    if (!end.landed) {
        PixelMapping missed;
        missed.launched = true;
        missed.steps = end.steps;
        return missed;
    }
    return landedAt(end.position, end.velocity, end.steps, sampler);
}

PixelMapping ScreenMap::mirror(const core::CameraRay& ray, DistanceField::Sampler& sampler) const
{
    MirrorHit hit;
    if (!intersectMirror(mFrame, ray, mParams.mirror, hit)) return {};
    const float half = float(vdb::kBoxHalfExtent);
    glm::vec3 p = hit.point;
    int steps = 0;
    for (; steps < mParams.mirror.maxSteps; ++steps) {
        if (std::abs(p.x) > half || std::abs(p.y) > half || std::abs(p.z) > half) break;
        const float phi = sampler.phi(p);
        if (phi < mEpsilon) return landedAt(p, hit.normal, steps, sampler);
        p += phi * hit.normal;
    }
    PixelMapping missed;
    missed.launched = true;
    missed.steps = steps;
    return missed;
}

PixelMapping ScreenMap::ring(const glm::dvec2& pixel) const
{
    glm::vec3 direction;
    if (!ringRayDirection(mRings, mFrame, pixel, direction)) return {};
    PixelMapping result;
    result.launched = true;
    const core::RayHit hit = mScene.bvh().intersect(mParams.ring.centre, direction);
    if (!hit.hit()) return result;
    result.region = Region::Indirect;
    result.point = pointOnTriangle(mScene.mesh(), hit.triangle, hit.barycentric);
    result.depth = glm::length(result.point.position - glm::vec3(mFrame.camera().eye));
    result.arrival = direction;
    return result;
}

}  // namespace ivis::render
