// The Fibonacci lattice: unit directions, spread evenly (their mean near the centre, every point of
// the sphere near one of them, none closer to another than a fraction of the even spacing).
#include <ivis/core/sphere_lattice.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ivis::core {
namespace {

TEST(SphereLattice, FibonacciDirectionsCoverTheSphereEvenly)
{
    const int count = 400;
    std::vector<glm::dvec3> directions;
    glm::dvec3 mean(0.0);
    for (int i = 0; i < count; ++i) {
        directions.push_back(fibonacciDirection(i, count));
        EXPECT_NEAR(glm::length(directions.back()), 1.0, 1e-12) << i;
        mean += directions.back() / double(count);
    }
    EXPECT_LT(glm::length(mean), 0.01);
    EXPECT_GT(directions.front().y, 0.99);
    EXPECT_LT(directions.back().y, -0.99);
    // Even in area: each direction's cap is 4 pi / count, about 10 degrees across at 400.
    const double spacing = glm::degrees(std::sqrt(4.0 * M_PI / count));
    auto degreesApart = [](const glm::dvec3& a, const glm::dvec3& b) {
        return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
    };
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < i; ++j) EXPECT_GT(degreesApart(directions[i], directions[j]), 0.5 * spacing) << i << " " << j;
    for (double theta = 1.0; theta < 180.0; theta += 3.0)
        for (double phi = 0.0; phi < 360.0; phi += 3.0) {
            const double t = glm::radians(theta), p = glm::radians(phi);
            const glm::dvec3 point(std::sin(t) * std::sin(p), std::cos(t), std::sin(t) * std::cos(p));
            double nearest = 180.0;
            for (const glm::dvec3& d : directions) nearest = std::min(nearest, degreesApart(point, d));
            EXPECT_LT(nearest, spacing) << theta << " " << phi;
        }
}

}  // namespace
}  // namespace ivis::core
