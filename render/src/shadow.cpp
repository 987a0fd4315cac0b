#include <ivis/render/shadow.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace ivis::render {

float shadowFactor(DistanceField::Sampler& sampler, const glm::vec3& point, const glm::vec3& normal,
                   const glm::vec3& toLight)
{
    constexpr float kSoftness = 8.0f;
    const float voxel = sampler.field().voxelSize();
    const float hitDistance = 0.5f * voxel;
    const glm::vec3 start = point + 2.0f * voxel * normal;
    float lit = 1.0f;
    float t = voxel;
    float previousSlope = 0.0f;  // d phi / dt at the previous sample
    for (int step = 0; step < 512 && t < 6.0f; ++step) {
        glm::vec3 gradient;
        const float phi = sampler.phiAndGradient(start + t * toLight, gradient);
        if (phi < hitDistance) return 0.0f;
        // An unsigned distance never goes negative: a wall thinner than the step shows up as phi
        // falling then rising again while it is within two voxels.
        const float slope = glm::dot(gradient, toLight);
        if (phi < 2.0f * voxel && previousSlope < 0.0f && slope > 0.0f && sampler.field().isUnsigned()) return 0.0f;
        previousSlope = slope;
        lit = std::min(lit, kSoftness * phi / t);
        t += std::max(phi, 0.5f * voxel);
    }
    return std::clamp(lit, 0.0f, 1.0f);
}

}  // namespace ivis::render
