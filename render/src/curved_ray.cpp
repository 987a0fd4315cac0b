#include <ivis/render/curved_ray.h>

#include <ivis/core/ray_box.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/common.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::render {

core::Bounds3 hullBounds(const core::TriangleMesh& mesh, float hullOffset, float voxelSize)
{
    core::Bounds3 box = core::bounds(mesh);
    const double grow = double(hullOffset) + voxelSize, half = vdb::kBoxHalfExtent;
    box.lo = glm::max(box.lo - grow, glm::dvec3(-half));
    box.hi = glm::min(box.hi + grow, glm::dvec3(half));
    return box;
}

bool findHullExit(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                  float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    const float minStep = 1e-4f;
    float tOutside = tExit;  // last parameter known to be outside the hull (phi > phi0)
    float t = tExit;
    while (t >= tEnter) {
        const float excess = sampler.phi(origin + t * direction) - hullOffset;
        if (excess <= 0.0f) {
            float lo = t, hi = tOutside;  // phi(lo) <= phi0 < phi(hi)
            while (hi - lo > 1e-5f) {
                const float mid = 0.5f * (lo + hi);
                (sampler.phi(origin + mid * direction) <= hullOffset ? lo : hi) = mid;
            }
            seed = origin + hi * direction;
            return true;
        }
        tOutside = t;
        t -= std::max(excess, minStep);
    }
    return false;
}

bool findClosestApproach(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                         float hullOffset, const core::Bounds3& hullBox, glm::vec3& seed, float& distance)
{
    float tEnter, tExit;
    if (!core::rayBoxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
    const float tolerance = 0.25f * sampler.field().voxelSize();
    float best = hullOffset, tBest = tEnter;
    for (float t = tEnter; t < tExit;) {
        const float phi = sampler.phi(origin + t * direction);
        if (phi < best) best = phi, tBest = t;
        // phi is 1-Lipschitz: nothing before t + (phi - best) comes below best (or below the hull).
        t += std::max(phi - best, tolerance);
    }
    if (!(best < hullOffset)) return false;
    // Golden-section search for the minimum around the best sample.
    float lo = std::max(tEnter, tBest - 2.0f * tolerance), hi = std::min(tExit, tBest + 2.0f * tolerance);
    const float ratio = 0.6180340f;
    while (hi - lo > 1e-5f) {
        const float a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
        if (sampler.phi(origin + a * direction) < sampler.phi(origin + b * direction)) hi = b;
        else lo = a;
    }
    const float t = 0.5f * (lo + hi);
    seed = origin + t * direction;
    distance = sampler.phi(seed);
    return distance < hullOffset;
}

glm::vec3 initialVelocity(const glm::vec3& gradient, const glm::vec3& viewDirection, float alpha)
{
    const float length = glm::length(gradient);
    if (!(length > 0.0f)) return alpha * viewDirection;
    const glm::vec3 g = gradient / length;
    return alpha * glm::cross(g, glm::cross(viewDirection, g));
}

float landingEpsilon(const CurvedRayParams& params, const DistanceField& field)
{
    return params.landingEpsilon > 0.0f ? params.landingEpsilon : 0.5f * field.voxelSize();
}

}  // namespace ivis::render
