#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

namespace ivis::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

using DirectedEdges = std::set<std::pair<std::uint32_t, std::uint32_t>>;

DirectedEdges directedEdges(const TriangleMesh& mesh)
{
    DirectedEdges edges;
    for (const auto& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) edges.insert({t[i], t[(i + 1) % 3]});
    return edges;
}

/// Signed volume; each boundary loop is closed by a fan to its centroid oriented like the mesh.
double signedVolume(const TriangleMesh& mesh)
{
    auto tet = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        return glm::dot(a, glm::cross(b, c)) / 6.0;
    };
    auto at = [&](std::uint32_t v) { return glm::dvec3(mesh.positions[v]); };
    double volume = 0.0;
    for (const auto& [a, b, c] : mesh.triangles) volume += tet(at(a), at(b), at(c));
    const DirectedEdges edges = directedEdges(mesh);
    for (const auto& loop : boundaryLoops(mesh)) {
        glm::dvec3 center(0.0);
        for (std::uint32_t v : loop) center += at(v) / double(loop.size());
        for (std::size_t i = 0; i < loop.size(); ++i) {
            std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
            if (edges.count({a, b})) std::swap(a, b);  // the cap runs the shared edge backwards
            volume += tet(center, at(a), at(b));
        }
    }
    return volume;
}

/// Facts every generated scene shares: sizes, names, normalisation, finite scalar, bounds,
/// no degenerate triangles, and consistent orientation (no directed edge used twice).
void expectWellFormedScene(const SurfaceField& field, const std::string& scene)
{
    const TriangleMesh& mesh = field.mesh;
    EXPECT_EQ(field.sourcePath, "generated:" + scene);
    EXPECT_FALSE(field.name.empty());
    EXPECT_EQ(field.values.size(), mesh.positions.size());
    EXPECT_EQ(mesh.dataTriangleCount, mesh.triangles.size());
    EXPECT_EQ(field.normalization.scale, 1.0);
    EXPECT_EQ(field.normalization.center, glm::dvec3(0.0));
    for (float v : field.values) ASSERT_TRUE(std::isfinite(v));
    const Bounds3 box = bounds(mesh);
    for (int a = 0; a < 3; ++a) {
        EXPECT_GE(box.lo[a], -1.0);
        EXPECT_LE(box.hi[a], 1.0);
    }
    std::size_t directedCount = 0;
    for (const auto& [a, b, c] : mesh.triangles) {
        const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
        ASSERT_GT(glm::length(glm::cross(pb - pa, pc - pa)), 0.0);
        directedCount += 3;
    }
    EXPECT_EQ(directedEdges(mesh).size(), directedCount);
}

long eulerCharacteristic(const TriangleMesh& mesh)
{
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& [a, b] : directedEdges(mesh)) edges.insert(std::minmax(a, b));
    return long(mesh.positions.size()) - long(edges.size()) + long(mesh.triangles.size());
}

const SurfaceField& vesselTree()
{
    static const SurfaceField field = makeVesselTree();
    return field;
}

TEST(ProceduralScenes, SphereVerticesOnUnitSphere)
{
    for (int s = 0; s <= 4; ++s) {
        const SurfaceField sphere = makeSphere(s);
        EXPECT_EQ(sphere.mesh.triangles.size(), 20u << (2 * s));
        EXPECT_EQ(sphere.mesh.positions.size(), 10u * (1u << (2 * s)) + 2u);
        for (const glm::vec3& p : sphere.mesh.positions)
            ASSERT_NEAR(glm::length(glm::dvec3(p)), 1.0, 1e-6);
    }
}

TEST(ProceduralScenes, SphereIsClosedAndOutward)
{
    const SurfaceField sphere = makeSphere(4);
    expectWellFormedScene(sphere, "sphere");
    EXPECT_EQ(sphere.name, "hotspots");
    EXPECT_EQ(boundaryEdgeCount(sphere.mesh), 0u);
    EXPECT_EQ(eulerCharacteristic(sphere.mesh), 2);
    EXPECT_NEAR(signedVolume(sphere.mesh), 4.0 / 3.0 * kPi, 0.02 * 4.0 / 3.0 * kPi);
}

TEST(ProceduralScenes, SphereHotSpotsPeakAtTheirCentres)
{
    const SurfaceField sphere = makeSphere(4);
    const glm::dvec3 back = glm::normalize(glm::dvec3(-0.64, -0.57, -0.52));
    std::size_t nearest = 0;
    for (std::size_t v = 0; v < sphere.mesh.positions.size(); ++v)
        if (glm::length(glm::dvec3(sphere.mesh.positions[v]) - back) <
            glm::length(glm::dvec3(sphere.mesh.positions[nearest]) - back))
            nearest = v;
    EXPECT_GT(sphere.values[nearest], 0.95f);
    EXPECT_LE(*std::max_element(sphere.values.begin(), sphere.values.end()), 1.01f);
}

TEST(ProceduralScenes, TorusIsClosedGenusOneAndFillsTheBox)
{
    const SurfaceField torus = makeTorus();
    expectWellFormedScene(torus, "torus");
    EXPECT_EQ(torus.name, "pattern");
    EXPECT_EQ(torus.mesh.triangles.size(), 2u * 96u * 48u);
    EXPECT_EQ(boundaryEdgeCount(torus.mesh), 0u);
    EXPECT_EQ(eulerCharacteristic(torus.mesh), 0);
    const Bounds3 box = bounds(torus.mesh);
    const double reach = std::max({-box.lo.x, -box.lo.y, -box.lo.z, box.hi.x, box.hi.y, box.hi.z});
    EXPECT_NEAR(reach, 1.0, 1e-6);
    const double scale = 1.0 / (0.7 + 0.3);  // outer radius becomes 1
    const double exact = 2.0 * kPi * kPi * (0.7 * scale) * (0.3 * scale) * (0.3 * scale);
    EXPECT_NEAR(signedVolume(torus.mesh), exact, 0.01 * exact);
}

TEST(ProceduralScenes, VesselTreeIsOneOpenComponentWithOneLoopPerEnd)
{
    const SurfaceField& tree = vesselTree();
    expectWellFormedScene(tree, "vessel-tree");
    EXPECT_EQ(tree.name, "wss");
    EXPECT_GE(tree.mesh.triangles.size(), 20000u);
    EXPECT_LE(tree.mesh.triangles.size(), 80000u);
    EXPECT_EQ(componentCount(tree.mesh), 1u);
    EXPECT_GT(boundaryEdgeCount(tree.mesh), 0u);
    EXPECT_GT(signedVolume(tree.mesh), 0.0);  // outward once the ends are closed

    const std::vector<detail::VesselEnd> ends = detail::vesselTreeEnds();
    ASSERT_EQ(ends.size(), 4u);
    const auto loops = boundaryLoops(tree.mesh);
    ASSERT_EQ(loops.size(), ends.size());
    std::set<std::size_t> matched;
    for (const auto& loop : loops) {
        // The loop lies on the end plane nearest to its first vertex, on a circle of that radius.
        const glm::dvec3 first(tree.mesh.positions[loop.front()]);
        std::size_t e = 0;
        for (std::size_t i = 1; i < ends.size(); ++i)
            if (glm::length(first - ends[i].center) < glm::length(first - ends[e].center)) e = i;
        matched.insert(e);
        EXPECT_GE(loop.size(), 24u);
        for (std::uint32_t v : loop) {
            const glm::dvec3 p(tree.mesh.positions[v]);
            ASSERT_NEAR(glm::dot(p - ends[e].center, ends[e].normal), 0.0, 1e-5);
            ASSERT_NEAR(glm::length(p - ends[e].center), ends[e].radius, 0.3 * ends[e].radius);
        }
    }
    EXPECT_EQ(matched.size(), ends.size());
}

TEST(ProceduralScenes, VesselTreeScalarPeaksOnTheBackSide)
{
    const SurfaceField& tree = vesselTree();
    const auto peak = std::max_element(tree.values.begin(), tree.values.end());
    EXPECT_LT(tree.mesh.positions[std::size_t(peak - tree.values.begin())].z, 0.0f);
    EXPECT_LE(*peak, 1.1f);
    EXPECT_GE(*std::min_element(tree.values.begin(), tree.values.end()), 0.0f);
}

TEST(ProceduralScenes, VesselTreeIsDeterministic)
{
    const SurfaceField again = makeVesselTree();
    EXPECT_EQ(again.mesh.positions, vesselTree().mesh.positions);
    EXPECT_EQ(again.mesh.triangles, vesselTree().mesh.triangles);
    EXPECT_EQ(again.values, vesselTree().values);
}

TEST(ProceduralScenes, CoarseVesselTreeKeepsItsTopology)
{
    const SurfaceField coarse = makeVesselTree(48);
    EXPECT_EQ(componentCount(coarse.mesh), 1u);
    EXPECT_EQ(boundaryLoops(coarse.mesh).size(), detail::vesselTreeEnds().size());
}

TEST(ProceduralScenes, RejectsBadParameters)
{
    EXPECT_THROW(makeSphere(-1), ValueError);
    EXPECT_THROW(makeTorus(2, 48), ValueError);
    EXPECT_THROW(makeVesselTree(8), ValueError);
}

TEST(ProceduralScenes, MakeSceneBuildsEveryNamedScene)
{
    for (const std::string& name : sceneNames())
        EXPECT_EQ(makeScene(name).sourcePath, "generated:" + name);
    try {
        makeScene("x");
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "unknown scene 'x' (known: sphere, torus, vessel-tree)");
    }
}

}  // namespace
}  // namespace ivis::core
