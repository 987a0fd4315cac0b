#include <ivis/core/cell_to_point.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace ivis::core {

std::vector<float> cellToPoint(const TriangleMesh& mesh, const std::vector<float>& perTriangle)
{
    IVIS_CHECK(perTriangle.size() == mesh.dataTriangleCount);
    std::vector<double> sum(mesh.positions.size(), 0.0), weight(mesh.positions.size(), 0.0);
    for (std::size_t t = 0; t < mesh.dataTriangleCount; ++t) {
        if (!std::isfinite(perTriangle[t])) continue;
        const auto& tri = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[tri[0]]);
        const double area = 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[tri[1]]) - a,
                                                         glm::dvec3(mesh.positions[tri[2]]) - a));
        for (const std::uint32_t v : tri) {
            sum[v] += area * perTriangle[t];
            weight[v] += area;
        }
    }
    std::vector<float> values(mesh.positions.size(), std::numeric_limits<float>::quiet_NaN());
    for (std::size_t v = 0; v < values.size(); ++v) {
        if (weight[v] > 0.0) values[v] = float(sum[v] / weight[v]);
    }
    return values;
}

}  // namespace ivis::core
