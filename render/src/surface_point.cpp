#include <ivis/render/surface_point.h>

#include <ivis/core/closest_point.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace ivis::render {

SurfacePoint projectOntoTriangle(const core::TriangleMesh& mesh, int triangle, const glm::vec3& p)
{
    const auto& t = mesh.triangles[triangle];
    const core::TrianglePoint closest =
        core::closestPointOnTriangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    return {triangle, glm::vec3(closest.barycentric), glm::vec3(closest.point)};
}

SurfacePoint pointOnTriangle(const core::TriangleMesh& mesh, int triangle, const glm::vec3& barycentric)
{
    const auto& t = mesh.triangles[triangle];
    const glm::vec3 position = barycentric.x * mesh.positions[t[0]] + barycentric.y * mesh.positions[t[1]] +
                               barycentric.z * mesh.positions[t[2]];
    return {triangle, barycentric, position};
}

float scalarAt(const core::SurfaceField& field, const SurfacePoint& point)
{
    if (!point.valid()) return std::numeric_limits<float>::quiet_NaN();
    return core::scalarAt(field, std::size_t(point.triangle), point.barycentric);
}

glm::vec3 triangleNormal(const core::TriangleMesh& mesh, int triangle)
{
    const auto& t = mesh.triangles[triangle];
    const glm::vec3 n =
        glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    const float length = glm::length(n);
    return length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

std::vector<glm::vec3> vertexNormals(const core::TriangleMesh& mesh)
{
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
    for (const auto& t : mesh.triangles) {
        const glm::vec3 n =
            glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
        for (std::uint32_t v : t) normals[v] += n;  // |n| is twice the area: area weighting
    }
    for (glm::vec3& n : normals) {
        const float length = glm::length(n);
        if (length > 0.0f) n /= length;
    }
    return normals;
}

glm::vec3 shadingNormal(const core::TriangleMesh& mesh, const std::vector<glm::vec3>& normals,
                        const SurfacePoint& point)
{
    const auto& t = mesh.triangles[point.triangle];
    const glm::vec3 n = point.barycentric.x * normals[t[0]] + point.barycentric.y * normals[t[1]] +
                        point.barycentric.z * normals[t[2]];
    const float length = glm::length(n);
    return length > 1e-3f ? n / length : triangleNormal(mesh, point.triangle);
}

}  // namespace ivis::render
