#include <ivis/render/curved_ray.h>

#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::render {
namespace {

/// Parameter interval of the ray inside the volume's box [-2.5,2.5]^3 (slab test).
bool boxInterval(const glm::vec3& origin, const glm::vec3& direction, float& tEnter, float& tExit)
{
    const float half = float(vdb::kBoxHalfExtent);
    tEnter = 0.0f;
    tExit = 1e30f;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(direction[a]) < 1e-12f) {
            if (origin[a] < -half || origin[a] > half) return false;
            continue;
        }
        float t0 = (-half - origin[a]) / direction[a], t1 = (half - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        tEnter = std::max(tEnter, t0);
        tExit = std::min(tExit, t1);
    }
    return tEnter < tExit;
}

}  // namespace

bool findHullExit(DistanceField::Sampler& sampler, const glm::vec3& origin, const glm::vec3& direction,
                  float hullOffset, glm::vec3& seed)
{
    float tEnter, tExit;
    if (!boxInterval(origin, direction, tEnter, tExit)) return false;
    const float minStep = 1e-4f;
    float tOutside = tExit;  // last parameter known to be outside the hull (phi > phi0)
    float t = tExit;
    while (t >= tEnter) {
        const float excess = sampler.phi(origin + t * direction) - hullOffset;
        if (excess <= 0.0f) {
            float lo = t, hi = tOutside;  // phi(lo) <= phi0 < phi(hi)
            for (int i = 0; i < 24; ++i) {
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

CurvedRayEnd traceCurvedRay(DistanceField::Sampler& sampler, const glm::vec3& seed, const glm::vec3& velocity,
                            const CurvedRayParams& params, float epsilon)
{
    CurvedRayEnd end;
    glm::vec3 p = seed, v = velocity, gradient;
    const float escape = sampler.field().reach() * 0.999f;
    for (int step = 0; step < params.maxSteps; ++step) {
        const float phi = sampler.phiAndGradient(p, gradient);
        if (phi < epsilon) {
            end.landed = true;
            break;
        }
        if (phi >= escape) break;
        v -= params.stepSize * gradient;
        const float speed = glm::length(v);
        const glm::vec3 heading = speed > 0.0f ? v / speed : -gradient;
        p += params.stepSize * phi * heading;
        ++end.steps;
    }
    end.position = p;
    end.velocity = v;
    return end;
}

}  // namespace ivis::render
