// ScreenMap (the map P: I -> S): direct pixels against an exhaustive Moller-Trumbore cast, indirect
// points on the surface with the scalar interpolated there, and back faces only for "backfaces".
#include "brute_force.h"
#include "render/scene_fixture.h"

#include <ivis/core/procedural_scenes.h>
#include <ivis/render/curved_ray_method.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/mirror_method.h>
#include <ivis/render/neugebauer_method.h>
#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace ivis::render {
namespace {

/// First hit of a ray over ALL triangles (plain Moller-Trumbore in double precision).
struct BruteHit {
    double t = std::numeric_limits<double>::infinity();
    int triangle = -1;
    glm::dvec3 point{0.0};
};

/// Whether the ray meets a mesh's bounding box @a box, grown by 1e-6 (slab test): a ray that misses
/// it cannot hit any triangle.
bool meetsBounds(const core::Bounds3& box, const glm::dvec3& origin, const glm::dvec3& direction)
{
    double tNear = 0.0, tFar = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        const double lo = box.lo[a] - 1e-6, hi = box.hi[a] + 1e-6;
        if (direction[a] == 0.0) {
            if (origin[a] < lo || origin[a] > hi) return false;
            continue;
        }
        double t0 = (lo - origin[a]) / direction[a], t1 = (hi - origin[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
    }
    return tNear <= tFar;
}

BruteHit castAll(const core::TriangleMesh& mesh, const glm::dvec3& origin, const glm::dvec3& direction,
                 bool backOnly = false, const core::Bounds3* box = nullptr)
{
    BruteHit best;
    if (box && !meetsBounds(*box, origin, direction)) return best;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& tri = mesh.triangles[i];
        const glm::dvec3 a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]), c(mesh.positions[tri[2]]);
        const glm::dvec3 e1 = b - a, e2 = c - a;
        const glm::dvec3 p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-18) continue;
        const double inv = 1.0 / det;
        const glm::dvec3 s = origin - a;
        const double u = glm::dot(s, p) * inv;
        if (u < 0.0 || u > 1.0) continue;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(direction, q) * inv;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = glm::dot(e2, q) * inv;
        if (!(t > 1e-9) || t >= best.t) continue;
        if (backOnly && glm::dot(glm::cross(e1, e2), direction) <= 0.0) continue;
        best.t = t;
        best.triangle = int(i);
        best.point = origin + t * direction;
    }
    return best;
}

/// Small closed and open surfaces for the exhaustive casts (BVH only needs the mesh; the volume is
/// coarse to keep the set-up fast).
const test::SceneFixture& smallSphere()
{
    static const test::SceneFixture fixture(core::makeSphere(3), 100);
    return fixture;
}
const test::SceneFixture& coarseSphere()
{
    static const test::SceneFixture fixture(core::makeSphere(2), 100);
    return fixture;
}
const test::SceneFixture& smallTorus()
{
    static const test::SceneFixture fixture(core::makeTorus(32, 16), 100);
    return fixture;
}
const test::SceneFixture& smallTree()
{
    static const test::SceneFixture fixture(core::makeVesselTree(32), 100);
    return fixture;
}

struct View {
    double theta, phi;
};
const View kViews[] = {{90, 0}, {63, 37}, {128, 212}, {20, 300}};

/// Compares the direct pixels of @a method with the exhaustive cast at 96x96 from the first
/// @a viewCount views.
void expectDirectPixelsMatchBruteForce(const test::SceneFixture& fixture, const std::string& method, const std::string& name,
                                       int viewCount = 4)
{
    const RenderScene& scene = *fixture.scene;
    const core::TriangleMesh& mesh = scene.mesh();
    const bool backOnly = method == "backfaces";
    const core::Bounds3 box = core::bounds(mesh);
    for (int v = 0; v < viewCount; ++v) {
        const View& view = kViews[v];
        const core::CameraFrame frame(core::Camera::fromAngles(view.theta, view.phi), 96, 96);
        const ScreenMap screen(scene, frame, makeMethod(method));
        auto sampler = scene.distance().sampler();
        int eitherDirect = 0, bothDirect = 0, regionMismatch = 0, triangleMismatch = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
                const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
                const BruteHit hit = castAll(mesh, ray.origin, ray.direction, backOnly, &box);
                const bool mapDirect = m.region == Region::Direct, bruteDirect = hit.triangle >= 0;
                if (!mapDirect && !bruteDirect) {
                    if (method == "front" || method == "backfaces") {
                        EXPECT_EQ(m.region, Region::Background);
                    }
                    continue;
                }
                ++eitherDirect;
                if (mapDirect != bruteDirect) {
                    ++regionMismatch;
                    continue;
                }
                ++bothDirect;
                if (m.point.triangle != hit.triangle) {
                    ++triangleMismatch;
                    // A different triangle is only acceptable on a shared edge: the same point.
                    EXPECT_LT(glm::length(glm::dvec3(m.point.position) - hit.point), 1e-4)
                        << name << " pixel " << x << "," << y;
                    continue;
                }
                EXPECT_LT(glm::length(glm::dvec3(m.point.position) - hit.point), 1e-4)
                    << name << " pixel " << x << "," << y;
                EXPECT_NEAR(m.depth, glm::length(hit.point - ray.origin), 1e-4);
                EXPECT_LT(glm::length(glm::dvec3(m.arrival) - ray.direction), 1e-6);
                EXPECT_FALSE(m.launched);
            }
        const std::string where = name + " view (" + std::to_string(view.theta) + ", " + std::to_string(view.phi) + ")";
        EXPECT_GT(bothDirect, 200) << where;  // the surface is in the picture
        EXPECT_LE(regionMismatch + triangleMismatch, 0.001 * eitherDirect)
            << where << ": " << regionMismatch << " region and " << triangleMismatch << " triangle mismatches of "
            << eitherDirect << " direct pixels";
    }
}

TEST(ScreenMap, DirectPixelsMatchExhaustiveRayCastOnSpheres)
{
    expectDirectPixelsMatchBruteForce(coarseSphere(), "front", "sphere(2)");
    expectDirectPixelsMatchBruteForce(smallSphere(), "front", "sphere(3)");
}

TEST(ScreenMap, DirectPixelsMatchExhaustiveRayCastOnTorus)
{
    expectDirectPixelsMatchBruteForce(smallTorus(), "front", "torus");
}

TEST(ScreenMap, DirectPixelsMatchExhaustiveRayCastOnVesselTree)
{
    // The indirect methods take the same straight-ray path for I+.
    expectDirectPixelsMatchBruteForce(smallTree(), "front", "tree");
    expectDirectPixelsMatchBruteForce(smallTree(), "inversevis", "tree/inversevis", 1);
}

TEST(ScreenMap, BackfacesShowsOnlyTrianglesFacingAway)
{
    for (const test::SceneFixture* fixture : {&smallSphere(), &smallTorus(), &smallTree()}) {
        const RenderScene& scene = *fixture->scene;
        for (const View& view : kViews) {
            const core::CameraFrame frame(core::Camera::fromAngles(view.theta, view.phi), 64, 64);
            const ScreenMap screen(scene, frame, makeMethod("backfaces"));
            auto sampler = scene.distance().sampler();
            int direct = 0;
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 64; ++x) {
                    const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
                    EXPECT_NE(m.region, Region::Indirect);
                    if (m.region != Region::Direct) continue;
                    ++direct;
                    const glm::dvec3 ray = frame.ray(x + 0.5, y + 0.5).direction;
                    EXPECT_GT(glm::dot(glm::dvec3(triangleNormal(scene.mesh(), m.point.triangle)), ray), 0.0)
                        << "pixel " << x << "," << y;
                }
            EXPECT_GT(direct, 100);
        }
    }
    // And the back face shown is the FIRST one along the ray.
    expectDirectPixelsMatchBruteForce(smallSphere(), "backfaces", "sphere(3)/backfaces");
    expectDirectPixelsMatchBruteForce(smallTree(), "backfaces", "tree/backfaces", 2);
}

/// Barycentric interpolation of the vertex values at the brute-force closest point to @a p.
float scalarByHand(const core::SurfaceField& field, const test::BruteForceClosest& brute, const glm::dvec3& p,
                   double& distance)
{
    std::int32_t triangle = -1;
    const core::TrianglePoint closest = brute.closest(p, &triangle);
    distance = std::sqrt(closest.distanceSquared);
    const auto& tri = field.mesh.triangles[std::size_t(triangle)];
    return float(closest.barycentric.x * field.values[tri[0]] + closest.barycentric.y * field.values[tri[1]] +
                 closest.barycentric.z * field.values[tri[2]]);
}

/// Every indirect pixel of @a params at 64x64: P on the surface, its scalar the interpolated one,
/// plus the method's own geometry (mirror: P lies along the mirror normal; ring: P is the first
/// hit of the ring ray from the centre).
void expectIndirectPointsOnSurface(const test::SceneFixture& fixture, const MethodPtr& method,
                                   const core::Camera& camera, const std::string& name)
{
    const RenderScene& scene = *fixture.scene;
    const core::SurfaceField& field = scene.field();
    ASSERT_TRUE(field.hasScalar());
    const test::BruteForceClosest brute(scene.mesh());
    const double voxel = fixture.volume.voxelSize();
    const auto [lo, hi] = core::finiteRange(field.values);
    const double tolerance = 1e-5 * std::max(1.0, double(hi - lo));
    const core::CameraFrame frame(camera, 64, 64);
    const ScreenMap screen(scene, frame, method);
    const auto* mirror = dynamic_cast<const MirrorMethod*>(method.get());
    const auto* ring = dynamic_cast<const NeugebauerMethod*>(method.get());
    const RingLayout rings = ring ? layoutRings(frame, scene.mesh(), ring->params()) : RingLayout{};
    auto sampler = scene.distance().sampler();
    int indirect = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
            if (m.region != Region::Indirect) continue;
            ++indirect;
            const std::string where = name + " pixel " + std::to_string(x) + "," + std::to_string(y);
            EXPECT_TRUE(m.launched) << where;
            ASSERT_TRUE(m.point.valid()) << where;
            const glm::dvec3 p(m.point.position);
            double distance = 0.0;
            const float expected = scalarByHand(field, brute, p, distance);
            EXPECT_LT(distance, voxel) << where;
            EXPECT_NEAR(scalarAt(field, m.point), expected, tolerance) << where;
            // The point's own triangle and weights reproduce it.
            const auto& tri = scene.mesh().triangles[std::size_t(m.point.triangle)];
            const glm::vec3 b = m.point.barycentric;
            EXPECT_NEAR(b.x + b.y + b.z, 1.0f, 1e-5f) << where;
            EXPECT_GE(std::min({b.x, b.y, b.z}), -1e-6f) << where;
            const glm::vec3 fromWeights =
                b.x * scene.mesh().positions[tri[0]] + b.y * scene.mesh().positions[tri[1]] + b.z * scene.mesh().positions[tri[2]];
            EXPECT_LT(glm::length(fromWeights - m.point.position), 1e-5f) << where;
            EXPECT_NEAR(m.depth, glm::length(p - camera.eye), 1e-4) << where;
            EXPECT_NEAR(glm::length(m.arrival), 1.0f, 1e-5f) << where;

            const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
            if (mirror) {
                MirrorHit hit;
                ASSERT_TRUE(intersectMirror(frame, ray, mirror->params(), hit)) << where;
                const glm::dvec3 n(hit.normal), offset = p - glm::dvec3(hit.point);
                EXPECT_LT(glm::length(offset - glm::dot(offset, n) * n), voxel) << where << ": off the mirror ray";
                EXPECT_GT(glm::dot(offset, n), 0.0) << where;
                EXPECT_LT(glm::length(m.arrival - hit.normal), 1e-5f) << where;
            } else if (ring) {
                glm::vec3 direction;
                ASSERT_TRUE(ringRayDirection(rings, frame, {x + 0.5, y + 0.5}, direction)) << where;
                const BruteHit hit = castAll(scene.mesh(), glm::dvec3(ring->params().centre), glm::dvec3(direction));
                ASSERT_GE(hit.triangle, 0) << where;
                EXPECT_LT(glm::length(hit.point - p), 1e-4) << where << ": not the first hit of the ring ray";
            }
        }
    EXPECT_GT(indirect, 100) << name;
}

TEST(ScreenMap, IndirectPointsLieOnTheSphereWithInterpolatedScalar)
{
    const auto& fixture = test::sphereScene();
    for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(50, 120)}) {
        expectIndirectPointsOnSurface(fixture, makeMethod("inversevis"), camera, "sphere/inversevis");
        expectIndirectPointsOnSurface(fixture, makeMethod("mirror", {{"mirror_w", {0.3f, 0.3f, 0.0f, 0.0f, 0.0f}}}),
                                      camera, "sphere/mirror(0.3,0.3)");
        expectIndirectPointsOnSurface(fixture, makeMethod("mirror", {{"mirror_w", {0.4f, 0.2f, 0.1f, 0.05f, -0.05f}}}),
                                      camera, "sphere/mirror(general)");
        expectIndirectPointsOnSurface(fixture, makeMethod("neugebauer"), camera, "sphere/neugebauer");
        expectIndirectPointsOnSurface(fixture, makeMethod("neugebauer", {{"ring_centre", {0.1f, -0.15f, 0.05f}}}),
                                      camera, "sphere/neugebauer(off-centre)");
    }
}

TEST(ScreenMap, IndirectPointsLieOnTheVesselTreeWithInterpolatedScalar)
{
    const auto& fixture = test::vesselScene();
    const core::Camera camera = core::Camera::fromAngles(90, 0);
    expectIndirectPointsOnSurface(fixture, makeMethod("inversevis"), camera, "tree/inversevis");
    expectIndirectPointsOnSurface(fixture, makeMethod("mirror", {{"mirror_w", {0.3f, 0.3f, 0.0f, 0.0f, 0.0f}}}), camera,
                                  "tree/mirror(0.3,0.3)");
    expectIndirectPointsOnSurface(fixture, makeMethod("neugebauer"), camera, "tree/neugebauer");
}

TEST(ScreenMap, ManyPixelsMapAsOneByOne)
{
    // mapMany traces a row's curved rays together (and relaunches the adaptive method's misses in
    // their lanes); every pixel must come out exactly as map() alone gives it, but for the hull
    // exit's last digits where findHullExits seeds the rays (its own test checks the seeds): there
    // a ray may take a step more or less and land a fraction of a voxel apart.
    const auto& fixture = test::sphereWithFarField();
    const core::CameraFrame frame(core::Camera::fromAngles(70, 30), 80, 80);
    // The adaptive method's steep profile sends its outer rays out of the field: they are launched again.
    const std::vector<std::pair<std::string, MethodPtr>> methods = {
        {"inversevis", makeMethod("inversevis")},
        {"inversevis-adaptive", makeMethod("inversevis-adaptive", {{"alpha_profile", {0.0f, 8.0f, 8.0f}}})},
        {"inversevis-wrap", makeMethod("inversevis-wrap")},
        {"neugebauer", makeMethod("neugebauer")},
        {"front", makeMethod("front")}};
    for (const auto& [method, instance] : methods) {
        SCOPED_TRACE(method);
        const ScreenMap screen(*fixture.scene, frame, instance);
        auto sampler = fixture.scene->distance().sampler();
        std::vector<glm::dvec2> positions;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x) positions.push_back({x + 0.5, y + 0.5});
        std::vector<PixelMapping> many(positions.size());
        screen.mapMany(positions.data(), positions.size(), sampler, many.data());
        int indirect = 0, launched = 0;
        const float voxel = fixture.scene->distance().voxelSize();
        const bool seededTogether = instance->curved() && instance->curved()->seedRule() == SeedRule::HullExit;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const PixelMapping one = screen.map(positions[i].x, positions[i].y, sampler);
            ASSERT_EQ(many[i].region, one.region) << i;
            ASSERT_EQ(many[i].launched, one.launched) << i;
            if (seededTogether) {
                EXPECT_LE(std::abs(many[i].steps - one.steps), 1) << i;
                EXPECT_LT(glm::length(many[i].point.position - one.point.position), 0.25f * voxel) << i;
            } else {
                ASSERT_EQ(many[i].steps, one.steps) << i;
                ASSERT_EQ(many[i].point.triangle, one.point.triangle) << i;
                ASSERT_EQ(many[i].point.position, one.point.position) << i;
                ASSERT_EQ(many[i].arrival, one.arrival) << i;
            }
            indirect += one.region == Region::Indirect;
            launched += one.launched;
        }
        if (method != "front") {
            EXPECT_GT(indirect, 500);
        }
        if (method.rfind("inversevis", 0) == 0) {
            EXPECT_GE(launched, indirect);
        }
    }
}

TEST(ScreenMap, FrontAndBackfacesLaunchNoIndirectRays)
{
    const auto& fixture = smallSphere();
    const core::CameraFrame frame(core::Camera::fromAngles(90, 0), 32, 32);
    for (const char* method : {"front", "backfaces"}) {
        const ScreenMap screen(*fixture.scene, frame, makeMethod(method));
        auto sampler = fixture.scene->distance().sampler();
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
                EXPECT_FALSE(m.launched);
                EXPECT_NE(m.region, Region::Indirect);
                if (m.region == Region::Background) { EXPECT_FALSE(m.point.valid()); }
            }
    }
}

}  // namespace
}  // namespace ivis::render
