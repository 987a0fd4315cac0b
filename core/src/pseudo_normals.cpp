#include <ivis/core/pseudo_normals.h>

#include <ivis/core/edge_key.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ivis::core {

PseudoNormals::PseudoNormals(const TriangleMesh& mesh)
    : mMesh(mesh), mFace(mesh.triangles.size()), mVertex(mesh.positions.size(), glm::dvec3(0.0))
{
    // Directed edge count per undirected edge: +1 for a->b with a < b, -1 for the reverse.
    std::unordered_map<std::uint64_t, int> direction, uses;
    double volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[tri[0]]), glm::dvec3(mesh.positions[tri[1]]),
                                 glm::dvec3(mesh.positions[tri[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(n);
        mFace[t] = length > 0.0 ? n / length : glm::dvec3(0.0);
        volume += glm::dot(p[0], glm::cross(p[1], p[2]));
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 e1 = p[(c + 1) % 3] - p[c], e2 = p[(c + 2) % 3] - p[c];
            const double l1 = glm::length(e1), l2 = glm::length(e2);
            if (l1 > 0.0 && l2 > 0.0)
                mVertex[tri[c]] += std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.0, 1.0)) * mFace[t];
            const std::uint32_t a = tri[c], b = tri[(c + 1) % 3];
            const std::uint64_t key = undirectedEdgeKey(a, b);
            direction[key] += a < b ? 1 : -1;
            ++uses[key];
            mEdge[key] += mFace[t];
        }
    }
    mUsable = !mesh.triangles.empty();
    for (const auto& [key, count] : uses)
        if (count != 2 || direction[key] != 0) mUsable = false;
    if (volume < 0.0) {  // consistently oriented inward: flip everything
        for (auto& n : mFace) n = -n;
        for (auto& n : mVertex) n = -n;
        for (auto& [key, n] : mEdge) n = -n;
    }
}

glm::dvec3 PseudoNormals::at(int triangle, const glm::dvec3& barycentric) const
{
    const auto& tri = mMesh.triangles[triangle];
    int zeros = 0, nonZero = 0;
    for (int c = 0; c < 3; ++c) {
        if (barycentric[c] <= 0.0) ++zeros;
        else nonZero = c;
    }
    if (zeros == 0) return mFace[triangle];
    if (zeros == 2) return mVertex[tri[nonZero]];
    const int skip = barycentric[0] <= 0.0 ? 0 : barycentric[1] <= 0.0 ? 1 : 2;
    return mEdge.at(undirectedEdgeKey(tri[(skip + 1) % 3], tri[(skip + 2) % 3]));
}

}  // namespace ivis::core
