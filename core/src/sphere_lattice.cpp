#include <ivis/core/sphere_lattice.h>

#include <cmath>

namespace ivis::core {

glm::dvec3 fibonacciDirection(int index, int count)
{
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    const double cosTheta = 1.0 - 2.0 * (index + 0.5) / count;
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    const double azimuth = golden * index;
    return {sinTheta * std::sin(azimuth), cosTheta, sinTheta * std::cos(azimuth)};
}

}  // namespace ivis::core
