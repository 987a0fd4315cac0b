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

PixelMapping ScreenMap::map(double x, double y, DistanceField::Sampler& sampler) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    const glm::vec3 origin(ray.origin), direction(ray.direction);
    const core::FaceFilter filter = mParams.method == Method::Backfaces ? core::FaceFilter::BackOnly : core::FaceFilter::Any;
    const core::RayHit hit = mScene.bvh().intersect(origin, direction, 0.0f, 1e30f, filter);
    if (hit.hit()) {
        PixelMapping direct;
        direct.region = Region::Direct;
        direct.point = pointOnTriangle(mScene.mesh(), hit.triangle, hit.barycentric);
        direct.depth = glm::length(direct.point.position - glm::vec3(mFrame.camera().eye));
        direct.arrival = direction;
        return direct;
    }
    switch (mParams.method) {
    case Method::InverseVis: return inverseVis(ray, sampler);
    case Method::Mirror: return mirror(ray, sampler);
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

bool ScreenMap::seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, glm::vec3& seed,
                            glm::vec3& velocityPerAlpha) const
{
    const glm::vec3 direction(ray.direction);
    if (!findHullExit(sampler, glm::vec3(ray.origin), direction, mParams.curved.hullOffset, mHullBox, seed))
        return false;
    glm::vec3 gradient;
    sampler.phiAndGradient(seed, gradient);
    velocityPerAlpha = initialVelocity(gradient, direction, 1.0f);
    return true;
}

bool ScreenMap::curvedRayStart(double x, double y, DistanceField::Sampler& sampler, glm::vec3& seed,
                               glm::vec3& velocityPerAlpha) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    if (mScene.bvh().intersect(glm::vec3(ray.origin), glm::vec3(ray.direction)).hit()) return false;
    return seedFromRay(ray, sampler, seed, velocityPerAlpha);
}

PixelMapping ScreenMap::inverseVis(const core::CameraRay& ray, DistanceField::Sampler& sampler) const
{
    glm::vec3 seed, velocityPerAlpha;
    if (!seedFromRay(ray, sampler, seed, velocityPerAlpha)) return {};
    const glm::vec3 v0 = mParams.curved.alpha * velocityPerAlpha;
    const CurvedRayEnd end = traceCurvedRay(sampler, seed, v0, mParams.curved, mEpsilon);
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
