#include <ivis/core/hole_capping.h>

#include <ivis/core/errors.h>

#include <limits>
#include <unordered_set>

namespace ivis::core {
namespace {

std::uint64_t halfedgeKey(std::uint32_t from, std::uint32_t to)
{
    return (std::uint64_t(from) << 32) | to;
}

}  // namespace

std::size_t capHoles(SurfaceField& field)
{
    TriangleMesh& mesh = field.mesh;
    IVIS_CHECK(mesh.dataTriangleCount <= mesh.triangles.size());
    const bool pointScalar = field.hasScalar() && field.valuesOn == Association::Point;
    IVIS_CHECK(!field.hasScalar() ||
               field.values.size() == (pointScalar ? mesh.positions.size() : mesh.dataTriangleCount));

    const std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(mesh);

    // Directed edges of the existing triangles: a cap triangle runs each boundary edge opposite
    // to the triangle beside it, so the orientation carries across the seam.
    std::unordered_set<std::uint64_t> halfedges;
    halfedges.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) halfedges.insert(halfedgeKey(t[k], t[(k + 1) % 3]));
    }

    std::size_t capped = 0;
    for (const std::vector<std::uint32_t>& loop : loops) {
        if (loop.size() < 3) continue;
        glm::dvec3 centroid(0.0);
        for (std::uint32_t v : loop) centroid += glm::dvec3(mesh.positions[v]);
        centroid /= double(loop.size());

        const auto center = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.emplace_back(centroid);
        if (pointScalar) field.values.push_back(std::numeric_limits<float>::quiet_NaN());

        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::uint32_t a = loop[i];
            const std::uint32_t b = loop[(i + 1) % loop.size()];
            if (halfedges.count(halfedgeKey(a, b))) {
                mesh.triangles.push_back({b, a, center});
            } else if (halfedges.count(halfedgeKey(b, a))) {
                mesh.triangles.push_back({a, b, center});
            }
            // else: the closing pair of an open chain (non-manifold boundary), not an edge.
        }
        ++capped;
    }
    return capped;
}

}  // namespace ivis::core
