#include <ivis/render/curved_ray.h>

#include <ivis/vdb/surface_volume.h>

#include <glm/common.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::render {
namespace {

/// Parameter interval (t >= 0) of the ray inside @a box (slab test); false when it misses.
bool boxInterval(const glm::vec3& origin, const glm::vec3& direction, const core::Bounds3& box, float& tEnter,
                 float& tExit)
{
    tEnter = 0.0f;
    tExit = 1e30f;
    for (int a = 0; a < 3; ++a) {
        const float lo = float(box.lo[a]), hi = float(box.hi[a]);
        if (std::abs(direction[a]) < 1e-12f) {
            if (origin[a] < lo || origin[a] > hi) return false;
            continue;
        }
        float t0 = (lo - origin[a]) / direction[a], t1 = (hi - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    return tEnter < tExit;
}

}  // namespace

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
    if (!boxInterval(origin, direction, hullBox, tEnter, tExit)) return false;
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
