// The generated sphere (scene:sphere): an icosphere with two hot spots.
#include <ivis/core/procedural_scenes.h>

#include "generated_field.h"

#include <ivis/core/edge_key.h>
#include <ivis/core/errors.h>

#include <glm/geometric.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace ivis::core {
namespace {

TriangleMesh icosahedron()
{
    const double t = 0.5 * (1.0 + std::sqrt(5.0));
    TriangleMesh mesh;
    for (const glm::dvec3& p :
         {glm::dvec3(-1, t, 0), glm::dvec3(1, t, 0), glm::dvec3(-1, -t, 0), glm::dvec3(1, -t, 0),
          glm::dvec3(0, -1, t), glm::dvec3(0, 1, t), glm::dvec3(0, -1, -t), glm::dvec3(0, 1, -t),
          glm::dvec3(t, 0, -1), glm::dvec3(t, 0, 1), glm::dvec3(-t, 0, -1), glm::dvec3(-t, 0, 1)})
        mesh.positions.emplace_back(glm::normalize(p));
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    return mesh;
}

/// Splits every triangle in four at its edge midpoints, projected onto the unit sphere.
void subdivideOnSphere(TriangleMesh& mesh)
{
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
    auto middle = [&](std::uint32_t a, std::uint32_t b) {
        const auto [it, isNew] = midpoint.try_emplace(undirectedEdgeKey(a, b), 0u);
        if (isNew) {
            it->second = std::uint32_t(mesh.positions.size());
            mesh.positions.emplace_back(glm::normalize(glm::dvec3(mesh.positions[a]) +
                                                       glm::dvec3(mesh.positions[b])));
        }
        return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    finer.reserve(4 * mesh.triangles.size());
    for (const auto& [a, b, c] : mesh.triangles) {
        const std::uint32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
        finer.insert(finer.end(), {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(finer);
}

}  // namespace

SurfaceField makeSphere(int subdivisions)
{
    if (subdivisions < 0 || subdivisions > 8)
        throw ValueError("makeSphere: subdivisions must be in [0, 8], got " +
                         std::to_string(subdivisions));
    TriangleMesh mesh = icosahedron();
    for (int i = 0; i < subdivisions; ++i) subdivideOnSphere(mesh);
    const glm::dvec3 front = glm::normalize(glm::dvec3(0.5, 0.3, 0.81));
    const glm::dvec3 back = glm::normalize(glm::dvec3(-0.64, -0.57, -0.52));
    return generated::makeField(std::move(mesh), "sphere", "hotspots", [&](const glm::dvec3& p) {
        return generated::gaussian(p, front, 0.2) + generated::gaussian(p, back, 0.2);
    });
}

}  // namespace ivis::core
