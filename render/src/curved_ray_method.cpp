#include <ivis/render/curved_ray_method.h>

#include <glm/geometric.hpp>

namespace ivis::render {

std::vector<ParameterSpec> curvedRaySpecs()
{
    const CurvedRayParams defaults;
    return {{"hull_offset", "hull distance phi0 (normalised units; below the volume's --reach)", {defaults.hullOffset},
             0.01f, 1.9f, false, false, true},
            {"step", "symplectic Euler step h", {defaults.stepSize}, 0.001f, 1.0f},
            {"max_steps", "steps before a curved ray counts as a miss", {float(defaults.maxSteps)}, 1.0f, 100000.0f,
             false, true}};
}

CurvedRayParams curvedRayParamsFrom(const ParameterValues& values)
{
    CurvedRayParams params;
    params.hullOffset = values.at("hull_offset")[0];
    params.stepSize = values.at("step")[0];
    params.maxSteps = int(values.at("max_steps")[0]);
    return params;
}

ParameterValues curvedRayValues(const CurvedRayParams& params)
{
    return {{"hull_offset", {params.hullOffset}}, {"step", {params.stepSize}}, {"max_steps", {float(params.maxSteps)}}};
}

std::unique_ptr<IndirectMap> CurvedRayMethod::indirectMap(const RenderScene& scene, const core::CameraFrame& frame) const
{
    return std::make_unique<CurvedRayMap>(scene, frame, *this);
}

PictureExtent CurvedRayMethod::pictureExtent(const RenderScene& scene, const core::Camera& camera) const
{
    return offsetMeshExtent(scene.mesh(), camera, mRay.hullOffset);
}

CurvedRayMap::CurvedRayMap(const RenderScene& scene, const core::CameraFrame& frame, const CurvedRayMethod& method)
    : mScene(scene),
      mFrame(frame),
      mMethod(method),
      mHullBox(hullBounds(scene.mesh(), method.rayParams().hullOffset, scene.distance().voxelSize())),
      mEpsilon(landingEpsilon(method.rayParams(), scene.distance()))
{
}

bool CurvedRayMap::seedFromRay(const core::CameraRay& ray, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    const glm::vec3 direction(ray.direction);
    const float hullOffset = mMethod.rayParams().hullOffset;
    if (mMethod.seedRule() == SeedRule::ClosestApproach) {
        float distance;
        if (!findClosestApproach(sampler, glm::vec3(ray.origin), direction, hullOffset, mHullBox, start.seed, distance))
            return false;
        start.ring = distance / hullOffset;
    } else if (!findHullExit(sampler, glm::vec3(ray.origin), direction, hullOffset, mHullBox, start.seed)) {
        return false;
    }
    glm::vec3 gradient;
    sampler.phiAndGradient(start.seed, gradient);
    start.velocityPerAlpha = initialVelocity(gradient, direction, 1.0f);
    const float length = glm::length(gradient);
    start.alignment = length > 0.0f ? glm::dot(direction, gradient) / length : 0.0f;
    return mMethod.aim(*this, start, sampler);
}

bool CurvedRayMap::start(double x, double y, DistanceField::Sampler& sampler, CurvedRayStart& start) const
{
    const core::CameraRay ray = mFrame.ray(x, y);
    if (mScene.bvh().intersect(glm::vec3(ray.origin), glm::vec3(ray.direction)).hit()) return false;
    return seedFromRay(ray, sampler, start);
}

CurvedRayTrace CurvedRayMap::trace(const CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    CurvedRayTrace result;
    for (;; ++result.launch) {
        const glm::vec3 velocity = mMethod.launchVelocity(start, result.launch);
        result.end = traceCurvedRay(sampler, start.seed, velocity, mMethod.rayParams(), mEpsilon);
        if (result.end.landed || result.launch == mMethod.relaunches() || velocity == glm::vec3(0.0f)) return result;
    }
}

PixelMapping CurvedRayMap::landedAt(const CurvedRayEnd& end, DistanceField::Sampler& sampler) const
{
    return render::landedAt(mScene, mFrame, end.position, end.velocity, end.steps, sampler);
}

PixelMapping CurvedRayMap::landing(const CurvedRayStart& start, DistanceField::Sampler& sampler) const
{
    const CurvedRayEnd end = trace(start, sampler).end;
    return end.landed ? landedAt(end, sampler) : launchedMiss(end.steps);
}

PixelMapping CurvedRayMap::map(double x, double y, DistanceField::Sampler& sampler) const
{
    CurvedRayStart start;
    if (!seedFromRay(mFrame.ray(x, y), sampler, start)) return {};
    return landing(start, sampler);
}

}  // namespace ivis::render
