#include <ivis/render/shadow.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace ivis::render {
namespace {

/// Euclidean distance from p to the box [lo, hi] (0 inside it).
float distanceToBox(const glm::vec3& p, const glm::vec3& lo, const glm::vec3& hi)
{
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f)));
}

/// Whether the ray from p along d never enters the box again: on some axis p lies beyond the box
/// and d does not turn back.
bool leavesBox(const glm::vec3& p, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi)
{
    for (int a = 0; a < 3; ++a)
        if ((p[a] > hi[a] && d[a] >= 0.0f) || (p[a] < lo[a] && d[a] <= 0.0f)) return true;
    return false;
}

}  // namespace

float shadowFactor(DistanceField::Sampler& sampler, const glm::vec3& point, const glm::vec3& normal,
                   const glm::vec3& toLight, const core::Bounds3& surfaceBox)
{
    const float voxel = sampler.field().voxelSize();
    const float hitDistance = kShadowHitVoxels * voxel;
    const glm::vec3 lo(surfaceBox.lo), hi(surfaceBox.hi);
    const glm::vec3 start = point + kShadowStartVoxels * voxel * normal;
    float lit = 1.0f;
    float t = voxel;
    float previousSlope = 0.0f;  // d phi / dt at the previous sample
    for (int step = 0; step < kShadowMaxSteps && t < kShadowMaxDistance; ++step) {
        const glm::vec3 p = start + t * toLight;
        glm::vec3 gradient;
        const float phi = sampler.phiAndGradient(p, gradient);
        if (phi < hitDistance) return 0.0f;
        // An unsigned distance never goes negative: a wall thinner than the step shows up as phi
        // falling then rising again while it is within two voxels.
        const float slope = glm::dot(gradient, toLight);
        if (phi < kShadowWallVoxels * voxel && previousSlope < 0.0f && slope > 0.0f && sampler.field().isUnsigned()) return 0.0f;
        previousSlope = slope;
        // Beyond the field's reach phi is clamped; the distance to the surface's box bounds the
        // true distance from below there, so a ray leaving the object is not darkened by the clamp,
        // and it ends once it has left the box for good.
        const float distance = std::max(phi, distanceToBox(p, lo, hi));
        lit = std::min(lit, kShadowSoftness * distance / t);
        if (leavesBox(p, toLight, lo, hi)) break;  // nothing ahead can shadow it
        t += std::max(distance, kShadowLeastStepVoxels * voxel);
    }
    return std::clamp(lit, 0.0f, 1.0f);
}

}  // namespace ivis::render
