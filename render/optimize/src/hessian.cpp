#include <ivis/optimize/hessian.h>

namespace ivis::optimize {

float HessianSampler::phiGradientJacobian(const glm::vec3& p, glm::vec3& gradient, glm::mat3& jacobian,
                                         glm::vec3& slope)
{
    const float value = mSampler.phiAndGradient(p, gradient);
    const float h = kHessianStep * mSampler.field().servingVoxelSize(value);
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 offset(0.0f), up, down;
        offset[axis] = h;
        const float above = mSampler.phiAndGradient(p + offset, up);
        const float below = mSampler.phiAndGradient(p - offset, down);
        jacobian[axis] = (up - down) / (2.0f * h);
        slope[axis] = (above - below) / (2.0f * h);
    }
    return value;
}

}  // namespace ivis::optimize
