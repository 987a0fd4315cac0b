#include <ivis/render/screen_map.h>

#include <ivis/render/curved_ray.h>
#include <ivis/render/quadratic_mirror.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace ivis::render {

ScreenMap::ScreenMap(const RenderScene& scene, const core::CameraFrame& frame, const MethodParams& params)
    : mScene(scene), mFrame(frame), mParams(params), mEpsilon(landingEpsilon(params.curved, scene.distance()))
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
    const int triangle = sampler.nearestTriangle(p);
    if (triangle < 0) return result;
    result.region = Region::Indirect;
    result.point = projectOntoTriangle(mScene.mesh(), triangle, p);
    result.depth = glm::length(result.point.position - glm::vec3(mFrame.camera().eye));
    const float length = glm::length(arrival);
    result.arrival = length > 0.0f ? arrival / length : glm::vec3(mFrame.forward());
    return result;
}

PixelMapping ScreenMap::inverseVis(const core::CameraRay& ray, DistanceField::Sampler& sampler) const
{
    const glm::vec3 direction(ray.direction);
    glm::vec3 seed;
    if (!findHullExit(sampler, glm::vec3(ray.origin), direction, mParams.curved.hullOffset, seed)) return {};
    glm::vec3 gradient;
    sampler.phiAndGradient(seed, gradient);
    const glm::vec3 v0 = initialVelocity(gradient, direction, mParams.curved.alpha);
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
