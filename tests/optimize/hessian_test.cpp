// The Hessian sampler of the tangent-linear curved rays, in the far field of a unit sphere: its
// Jacobian of the gradient against the Jacobian of the trilinear blend of the brute-force exact gradients at the
// cell's corners, and its slope of phi against the gradient.
#include "brute_force.h"
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/optimize/hessian.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace ivis::optimize {
namespace {

TEST(HessianSampler, IsTheJacobianOfTheBlendedExactGradients)
{
    const auto& fixture = test::sphereWithFarField();
    const test::BruteForceClosest brute(fixture.field.mesh);
    const vdb::BoxLattice lattice = fixture.scene->volume().farLattice();
    auto sampler = fixture.scene->distance().sampler();
    HessianSampler hessianSampler(sampler);
    for (const double radius : {1.3, 1.4, 1.5}) {
        for (const glm::vec3& n : test::fibonacciDirections(60)) {
            // The centre of the far-field cell containing radius * n: the difference step stays inside it.
            glm::dvec3 cell, p;
            for (int a = 0; a < 3; ++a) {
                cell[a] = std::floor(lattice.indexFromWorld(radius * n[a]));
                p[a] = lattice.worldFromIndex(cell[a] + 0.5);
            }
            // d/dx_a of sum_i w_i g_i at the centre, where the weights' derivative is +-1/4 per voxel.
            glm::dmat3 jacobian(0.0);
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 corner(i & 1, (i >> 1) & 1, (i >> 2) & 1);
                glm::dvec3 x;
                for (int a = 0; a < 3; ++a) x[a] = lattice.worldFromIndex(cell[a] + corner[a]);
                const glm::dvec3 g = brute.distanceGradient(x);
                for (int a = 0; a < 3; ++a) jacobian[a] += (corner[a] > 0.0 ? 0.25 : -0.25) / lattice.voxelSize() * g;
            }
            glm::vec3 gradient, slope;
            glm::mat3 sampled;
            const float phi = hessianSampler.phiGradientJacobian(glm::vec3(p), gradient, sampled, slope);
            EXPECT_NEAR(phi, glm::length(p) - 1.0, 0.01);
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    EXPECT_NEAR(sampled[a][b], jacobian[a][b], 2e-3) << "(" << a << "," << b << ") at radius " << radius;
            // phi's slope is the gradient up to the Taylor blend's O(voxel / radius) error.
            EXPECT_LT(glm::length(slope - gradient), 0.5 * lattice.voxelSize() / radius) << "at radius " << radius;
        }
    }
}

}  // namespace
}  // namespace ivis::optimize
