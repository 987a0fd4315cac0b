#include <ivis/render/pixel_mapping.h>

#include <ivis/render/render_scene.h>

#include <glm/geometric.hpp>

#include <limits>

namespace ivis::render {

PixelMapping launchedMiss(int steps)
{
    PixelMapping missed;
    missed.launched = true;
    missed.steps = steps;
    return missed;
}

PixelMapping landedAt(const RenderScene& scene, const core::CameraFrame& frame, const glm::vec3& p,
                      const glm::vec3& arrival, int steps, DistanceField::Sampler& sampler)
{
    PixelMapping result = launchedMiss(steps);
    // The triangle stored at the nearest voxel is closest to that voxel's centre; its distance to p
    // bounds a BVH search that returns the exact closest surface point of p.
    const int stored = sampler.nearestTriangle(p);
    const double bound = stored >= 0 ? glm::length(projectOntoTriangle(scene.mesh(), stored, p).position - p)
                                     : std::numeric_limits<double>::infinity();
    int triangle = -1;
    const core::TrianglePoint closest = scene.bvh().closestPoint(glm::dvec3(p), bound, triangle);
    if (triangle < 0) return result;
    result.region = Region::Indirect;
    result.point = {triangle, glm::vec3(closest.barycentric), glm::vec3(closest.point)};
    result.depth = glm::length(result.point.position - glm::vec3(frame.camera().eye));
    const float length = glm::length(arrival);
    result.arrival = length > 0.0f ? arrival / length : glm::vec3(frame.forward());
    return result;
}

PixelMapping straightHit(const RenderScene& scene, const core::CameraFrame& frame, const glm::vec3& origin,
                         const glm::vec3& direction)
{
    PixelMapping result = launchedMiss(0);
    const core::RayHit hit = scene.bvh().intersect(origin, direction);
    if (!hit.hit()) return result;
    result.region = Region::Indirect;
    result.point = pointOnTriangle(scene.mesh(), hit.triangle, hit.barycentric);
    result.depth = glm::length(result.point.position - glm::vec3(frame.camera().eye));
    result.arrival = direction;
    return result;
}

}  // namespace ivis::render
