// The Hessian sampler of the tangent-linear curved rays against the analytic Hessian of a sphere's
// distance, (I - n n^T) / r, in the far field away from the surface.
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/optimize/hessian.h>

#include <gtest/gtest.h>

namespace ivis::optimize {
namespace {

TEST(HessianSampler, IsSymmetricAndMatchesTheSphereAwayFromTheSurface)
{
    const auto& fixture = test::sphereWithFarField();
    auto sampler = fixture.scene->distance().sampler();
    HessianSampler hessianSampler(sampler);
    for (const float radius : {1.3f, 1.4f, 1.5f}) {
        for (const glm::vec3& n : test::fibonacciDirections(60)) {
            const glm::vec3 p = radius * n;
            glm::vec3 gradient;
            glm::mat3 hessian;
            const float phi = hessianSampler.phiGradientHessian(p, gradient, hessian);
            EXPECT_NEAR(phi, radius - 1.0f, 0.01f);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    EXPECT_EQ(hessian[i][j], hessian[j][i]);
                    const float exact = ((i == j ? 1.0f : 0.0f) - n[i] * n[j]) / radius;
                    EXPECT_NEAR(hessian[i][j], exact, 0.25f / radius) << "(" << i << "," << j << ") at radius " << radius;
                }
        }
    }
}

}  // namespace
}  // namespace ivis::optimize
