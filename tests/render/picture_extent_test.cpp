// offsetMeshExtent against its definition: the image-plane reach of the mesh grown by a ball, from
// the analytic tangent cone of one ball and from brute-force samples on every vertex's ball.
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

/// Largest |x| and |y| on the image plane over @a count points on the sphere of radius @a offset
/// around every vertex (brute force).
glm::dvec2 sampledReach(const core::TriangleMesh& mesh, const core::Camera& camera, double offset, int count)
{
    const core::CameraFrame frame(camera, 1, 1);
    const std::vector<glm::vec3> directions = test::fibonacciDirections(count);
    glm::dvec2 reach(0.0);
    for (const glm::vec3& p : mesh.positions)
        for (const glm::vec3& d : directions)
            reach = glm::max(reach, glm::abs(frame.imagePlane(glm::dvec3(p) + offset * glm::dvec3(d))));
    return reach;
}

// A ball of radius R at the target, seen from distance 2.5: the tangent cone's half-angle is
// asin(R / 2.5) on both axes, whatever the direction of view.
TEST(PictureExtent, BallAtTheTargetReachesTheTangentConesAngle)
{
    const core::TriangleMesh mesh = pointMesh(glm::vec3(0.0f));
    for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(20, 130),
                                       core::Camera::fromAngles(0, 0), core::Camera::fromAngles(160, -75)})
        for (double radius : {0.0, 0.4, 1.0, 1.4, 2.2}) {
            const PictureExtent extent = offsetMeshExtent(mesh, camera, radius);
            const double expected = std::tan(std::asin(radius / 2.5));
            EXPECT_NEAR(extent.imagePlane.x, expected, 1e-6) << radius;
            EXPECT_NEAR(extent.imagePlane.y, expected, 1e-6) << radius;
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
        const PictureExtent extent = offsetMeshExtent(mesh, camera, radius);
        const glm::dvec2 sampled = sampledReach(mesh, camera, radius, 20000);
        for (int axis = 0; axis < 2; ++axis) {
            EXPECT_LE(sampled[axis], extent.imagePlane[axis] + 1e-9) << "trial " << trial;
            EXPECT_GE(sampled[axis], extent.imagePlane[axis] - 2e-3) << "trial " << trial;
        }
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
            const PictureExtent extent = offsetMeshExtent(mesh, camera, offset);
            const glm::dvec2 sampled = sampledReach(mesh, camera, offset, offset > 0.0 ? 200 : 1);
            for (int axis = 0; axis < 2; ++axis) {
                EXPECT_LE(sampled[axis], extent.imagePlane[axis] + 1e-9);
                // 200 directions lie within about 8 degrees of any direction: cos(8 deg) of the offset.
                EXPECT_GE(sampled[axis], extent.imagePlane[axis] - (offset > 0.0 ? 0.01 * offset + 1e-9 : 1e-9));
            }
        }
}

// A ball that holds the eye, or reaches the plane through the eye across the view, cannot be
// framed; one just in front of that plane can, however far off the axis.
TEST(PictureExtent, BallReachingTheEyesPlaneIsUnbounded)
{
    const core::Camera camera = core::Camera::fromAngles(90, 0);  // eye (0, 0, 2.5) looking down -z
    EXPECT_TRUE(std::isinf(offsetMeshExtent(pointMesh(glm::vec3(0.0f, 0.0f, 2.0f)), camera, 0.6).imagePlane.x));
    const PictureExtent crossing = offsetMeshExtent(pointMesh(glm::vec3(1.0f, 0.0f, 2.4f)), camera, 0.2);
    EXPECT_TRUE(std::isinf(crossing.imagePlane.x));
    EXPECT_TRUE(std::isinf(crossing.imagePlane.y));
    const PictureExtent near = offsetMeshExtent(pointMesh(glm::vec3(1.0f, 0.0f, 2.29f)), camera, 0.2);
    EXPECT_TRUE(std::isfinite(near.imagePlane.x));
    EXPECT_GT(near.imagePlane.x, 50.0);
    EXPECT_THROW(offsetMeshExtent(pointMesh(glm::vec3(0.0f)), camera, -0.1), ValueError);
}

TEST(PictureExtent, UnitedTakesTheFartherReachOnEachAxis)
{
    const PictureExtent a{{0.2, 0.9}, {0.1, 0.0}}, b{{0.5, 0.3}, {0.0, 0.2}};
    const PictureExtent u = a.united(b);
    EXPECT_EQ(u.imagePlane, glm::dvec2(0.5, 0.9));
    EXPECT_EQ(u.fixed, glm::dvec2(0.1, 0.2));
}

}  // namespace
}  // namespace ivis::render
