// offsetMeshExtent against its definition: the image-plane reach of the mesh grown by a ball on
// either side of the view axis, from the analytic tangent cone of one ball and from brute-force
// samples on every vertex's ball.
#include "test_support.h"

#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/render/picture_extent.h>

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ivis::render {
namespace {

/// One triangle collapsed onto @a p: a mesh whose offset surface is the sphere around @a p.
core::TriangleMesh pointMesh(const glm::vec3& p)
{
    core::TriangleMesh mesh;
    mesh.positions = {p, p, p};
    mesh.triangles = {{0, 1, 2}};
    mesh.dataTriangleCount = 1;
    return mesh;
}

/// offsetMeshExtent of @a mesh's vertices in clusters of the default size.
PictureExtent meshExtent(const core::TriangleMesh& mesh, const core::Camera& camera, double offset)
{
    return offsetMeshExtent(core::ClusteredVertices(mesh.positions), camera, offset);
}

/// Least and greatest x and y on the image plane over @a count points on the sphere of radius
/// @a offset around every vertex (brute force).
PictureExtent sampledExtent(const core::TriangleMesh& mesh, const core::Camera& camera, double offset, int count)
{
    const core::CameraFrame frame(camera, 1, 1);
    const std::vector<glm::vec3> directions = test::fibonacciDirections(count);
    PictureExtent extent = PictureExtent::empty();
    for (const glm::vec3& p : mesh.positions)
        for (const glm::vec3& d : directions) {
            const glm::dvec2 s = frame.imagePlane(glm::dvec3(p) + offset * glm::dvec3(d));
            extent.lo = glm::min(extent.lo, s);
            extent.hi = glm::max(extent.hi, s);
        }
    return extent;
}

/// Expects @a sampled within [@a below, @a above] of @a exact on each side (the samples lie inside).
void expectSampledWithin(const PictureExtent& exact, const PictureExtent& sampled, double below, double above)
{
    for (int axis = 0; axis < 2; ++axis) {
        EXPECT_LE(sampled.hi[axis], exact.hi[axis] + above) << "axis " << axis;
        EXPECT_GE(sampled.hi[axis], exact.hi[axis] - below) << "axis " << axis;
        EXPECT_GE(sampled.lo[axis], exact.lo[axis] - above) << "axis " << axis;
        EXPECT_LE(sampled.lo[axis], exact.lo[axis] + below) << "axis " << axis;
    }
}

// A ball of radius R at the target, seen from distance 2.5: the tangent cone's half-angle is
// asin(R / 2.5) on both axes, whatever the direction of view.
TEST(PictureExtent, BallAtTheTargetReachesTheTangentConesAngle)
{
    const core::TriangleMesh mesh = pointMesh(glm::vec3(0.0f));
    for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(20, 130),
                                       core::Camera::fromAngles(0, 0), core::Camera::fromAngles(160, -75)})
        for (double radius : {0.0, 0.4, 1.0, 1.4, 2.2}) {
            const PictureExtent extent = meshExtent(mesh, camera, radius);
            const double expected = std::tan(std::asin(radius / 2.5));
            EXPECT_NEAR(extent.hi.x, expected, 1e-6) << radius;
            EXPECT_NEAR(extent.hi.y, expected, 1e-6) << radius;
            EXPECT_NEAR(extent.lo.x, -expected, 1e-6) << radius;
            EXPECT_NEAR(extent.lo.y, -expected, 1e-6) << radius;
            EXPECT_EQ(extent.fixed, glm::dvec2(0.0));
        }
}

// Off the view axis the cone is oblique: the reach is tan(angle of the centre + asin(R / distance))
// in the plane through the eye that holds the other axis; sampled points on the sphere approach it
// from below.
TEST(PictureExtent, BallOffTheAxisMatchesSampledPointsOnItsSphere)
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const glm::vec3 centre(uniform(random), uniform(random), uniform(random));
        const double radius = 0.5 * (uniform(random) + 1.0) * 0.6;
        core::Camera camera = core::Camera::fromAngles(90.0 * (uniform(random) + 1.0), 180.0 * uniform(random));
        camera.orthographic = trial % 4 == 3;
        const core::TriangleMesh mesh = pointMesh(centre);
        const PictureExtent extent = meshExtent(mesh, camera, radius);
        SCOPED_TRACE("trial " + std::to_string(trial));
        expectSampledWithin(extent, sampledExtent(mesh, camera, radius, 20000), 2e-3, 1e-9);
    }
}

// On a real mesh the reach is the offset surface's: attained on some vertex's ball and never
// exceeded by any sampled point of any ball (the vessel tree, 70k triangles, seen from four views).
TEST(PictureExtent, MeshGrownByTheHullOffsetMatchesBruteForce)
{
    const core::TriangleMesh mesh = core::makeVesselTree().mesh;
    for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(40, 60),
                                       core::Camera::fromAngles(130, 200), core::Camera::fromAngles(5, -20)})
        for (double offset : {0.0, 0.4}) {
            const PictureExtent extent = meshExtent(mesh, camera, offset);
            // 200 directions lie within about 8 degrees of any direction: cos(8 deg) of the offset.
            expectSampledWithin(extent, sampledExtent(mesh, camera, offset, offset > 0.0 ? 200 : 1),
                                offset > 0.0 ? 0.01 * offset + 1e-9 : 1e-9, 1e-9);
        }
}

// A ball that holds the eye, or reaches the plane through the eye across the view, cannot be
// framed; one just in front of that plane can, however far off the axis.
TEST(PictureExtent, BallReachingTheEyesPlaneIsUnbounded)
{
    const core::Camera camera = core::Camera::fromAngles(90, 0);  // eye (0, 0, 2.5) looking down -z
    EXPECT_TRUE(std::isinf(meshExtent(pointMesh(glm::vec3(0.0f, 0.0f, 2.0f)), camera, 0.6).hi.x));
    // Beside the eye on its right, across its plane: unbounded to the right and up and down, not to the left.
    const PictureExtent crossing = meshExtent(pointMesh(glm::vec3(1.0f, 0.0f, 2.4f)), camera, 0.2);
    EXPECT_TRUE(std::isinf(crossing.hi.x));
    EXPECT_TRUE(std::isinf(crossing.hi.y));
    EXPECT_TRUE(std::isinf(crossing.lo.y));
    EXPECT_NEAR(crossing.lo.x, std::tan(std::atan(1.0 / 0.1) - std::asin(0.2 / std::sqrt(1.01))), 1e-5);  // float positions
    const PictureExtent near = meshExtent(pointMesh(glm::vec3(1.0f, 0.0f, 2.29f)), camera, 0.2);
    EXPECT_TRUE(std::isfinite(near.hi.x));
    EXPECT_GT(near.hi.x, 50.0);
    EXPECT_THROW(meshExtent(pointMesh(glm::vec3(0.0f)), camera, -0.1), ValueError);
}

// Clusters only skip work: with one vertex per cluster, the default size and one cluster of all
// (every vertex measured) the extent is the same to the last bit, from far views, from eyes inside
// the grown mesh or beside it (unbounded sides) and orthographic ones.
TEST(PictureExtent, ClustersNeverChangeTheExtent)
{
    const core::TriangleMesh mesh = core::makeVesselTree().mesh;
    const core::ClusteredVertices single(mesh.positions, 1), clustered(mesh.positions),
        whole(mesh.positions, mesh.positions.size());
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    int unbounded = 0;
    for (int trial = 0; trial < 60; ++trial) {
        core::Camera camera = core::Camera::fromAngles(180.0 * uniform(random), 360.0 * uniform(random));
        camera.eye *= trial % 3 == 0 ? 0.3 + 0.5 * uniform(random) : 1.0;  // a third from within or beside the mesh
        camera.orthographic = trial % 5 == 4;
        for (double offset : {0.0, 0.4, 1.0}) {
            const PictureExtent reference = offsetMeshExtent(whole, camera, offset);
            for (const core::ClusteredVertices* vertices : {&single, &clustered}) {
                const PictureExtent extent = offsetMeshExtent(*vertices, camera, offset);
                EXPECT_EQ(extent.lo, reference.lo) << "trial " << trial << " offset " << offset;
                EXPECT_EQ(extent.hi, reference.hi) << "trial " << trial << " offset " << offset;
            }
            unbounded += std::isinf(reference.hi.x) || std::isinf(reference.lo.y);
        }
    }
    EXPECT_GT(unbounded, 0);  // the near eyes reached the unbounded case
    EXPECT_LT(unbounded, 150);
}

TEST(PictureExtent, UnitedTakesTheFartherReachOnEachSide)
{
    const PictureExtent a{{-0.2, 0.1}, {0.4, 0.9}, {0.1, 0.0}}, b{{-0.5, -0.3}, {0.1, 1.2}, {0.0, 0.2}};
    const PictureExtent u = a.united(b);
    EXPECT_EQ(u.lo, glm::dvec2(-0.5, -0.3));
    EXPECT_EQ(u.hi, glm::dvec2(0.4, 1.2));
    EXPECT_EQ(u.fixed, glm::dvec2(0.1, 0.2));
    const PictureExtent same = a.united(PictureExtent::empty());
    EXPECT_EQ(same.lo, a.lo);
    EXPECT_EQ(same.hi, a.hi);
}

}  // namespace
}  // namespace ivis::render
