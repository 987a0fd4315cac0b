#include <ivis/render/shadow.h>

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
    for (int step = 0; step < 256 && t < 6.0f; ++step) {
        const float phi = sampler.phi(start + t * toLight);
        if (phi < hitDistance) return 0.0f;
        lit = std::min(lit, kSoftness * phi / t);
        t += std::max(phi, voxel);
    }
    return std::clamp(lit, 0.0f, 1.0f);
}

}  // namespace ivis::render
