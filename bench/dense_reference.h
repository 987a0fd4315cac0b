/// @file dense_reference.h
/// @brief The benchmark's reference sampler: a plain dense float array of the distance at the fine
///        voxel size, trilinear value and the analytic gradient of the trilinear cell (the
///        memory-bound ceiling a curved-ray step can reach).
#pragma once

#include <ivis/render/render_scene.h>

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace ivis::bench {

/// @brief Dense float box of phi sampled from a scene's distance field at the fine voxel size.
class DenseReference {
public:
    /// @brief Samples phi at every fine voxel centre of the box the far field (or the band) covers.
    explicit DenseReference(const render::RenderScene& scene);

    /// @brief Trilinear phi at p and the analytic gradient of its cell (background outside the box).
    float phiAndGradient(const glm::vec3& p, glm::vec3& gradient) const;
    /// @brief Bytes held by the value array.
    std::size_t memoryBytes() const { return mValues.size() * sizeof(float); }

private:
    std::vector<float> mValues;
    std::array<int, 3> mDims{0, 0, 0};
    glm::vec3 mOrigin{0.0f};  ///< world position of voxel (0,0,0)
    float mInvVoxelSize = 1.0f;
    float mBackground = 0.0f;
};

/// @brief FieldSampler facade (render::integrateCurvedRay) over a DenseReference.
struct DenseReferenceSampler {
    const DenseReference* reference;
    /// @brief DenseReference::phiAndGradient.
    float phiAndGradient(const glm::vec3& p, glm::vec3& gradient) { return reference->phiAndGradient(p, gradient); }
};

}  // namespace ivis::bench
