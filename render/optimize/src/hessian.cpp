#include <ivis/optimize/hessian.h>

#include <glm/matrix.hpp>

namespace ivis::optimize {

float HessianSampler::phiGradientHessian(const glm::vec3& p, glm::vec3& gradient, glm::mat3& hessian)
{
    const float value = mSampler.phiAndGradient(p, gradient);
    const float h = mSampler.field().servingVoxelSize(value);
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 offset(0.0f), up, down;
        offset[axis] = h;
        mSampler.phiAndGradient(p + offset, up);
        mSampler.phiAndGradient(p - offset, down);
        hessian[axis] = (up - down) / (2.0f * h);
    }
    hessian = 0.5f * (hessian + glm::transpose(hessian));
    return value;
}

}  // namespace ivis::optimize
