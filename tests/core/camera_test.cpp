// Camera: the documented angle convention (including the poles), ray/project as inverses for both
// projections, the window centre's shift, angles() as the inverse of fromAngles, and the JSON files.
#include <ivis/core/camera.h>
#include <ivis/core/errors.h>

#include "test_support.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {
namespace {

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance, const std::string& what)
{
    EXPECT_LE(glm::length(actual - expected), tolerance)
        << what << ": (" << actual.x << ", " << actual.y << ", " << actual.z << ") expected (" << expected.x
        << ", " << expected.y << ", " << expected.z << ")";
}

/// The frame's basis is orthonormal, right-handed (right x up = -forward) and looks at the target.
void expectValidBasis(const CameraFrame& frame, const std::string& what)
{
    const Camera& camera = frame.camera();
    expectNear(frame.forward(), glm::normalize(camera.target - camera.eye), 1e-12, what + " forward");
    EXPECT_NEAR(glm::length(frame.right()), 1.0, 1e-12) << what;
    EXPECT_NEAR(glm::length(frame.upVector()), 1.0, 1e-12) << what;
    EXPECT_NEAR(glm::dot(frame.right(), frame.forward()), 0.0, 1e-12) << what;
    EXPECT_NEAR(glm::dot(frame.upVector(), frame.forward()), 0.0, 1e-12) << what;
    EXPECT_NEAR(glm::dot(frame.right(), frame.upVector()), 0.0, 1e-12) << what;
    expectNear(glm::cross(frame.right(), frame.upVector()), -frame.forward(), 1e-12, what + " handedness");
}

TEST(Camera, FromAnglesPutsTheEyeWhereDocumented)
{
    const double r = kCameraDistance;
    struct Case {
        double theta, phi;
        glm::dvec3 eye;
    };
    // theta from +y, phi around y from +z toward +x.
    for (const Case& c : {Case{90, 0, {0, 0, r}}, Case{90, 90, {r, 0, 0}}, Case{0, 0, {0, r, 0}},
                          Case{180, 0, {0, -r, 0}}, Case{90, 180, {0, 0, -r}}, Case{90, -90, {-r, 0, 0}},
                          Case{45, 0, {0, r * std::sqrt(0.5), r * std::sqrt(0.5)}}}) {
        const std::string what = "theta " + std::to_string(c.theta) + " phi " + std::to_string(c.phi);
        const Camera camera = Camera::fromAngles(c.theta, c.phi);
        expectNear(camera.eye, c.eye, 1e-12, what);
        expectNear(camera.target, glm::dvec3(0.0), 0.0, what);
        EXPECT_EQ(camera.fovYDeg, kDefaultFovYDeg);
        EXPECT_NO_THROW(camera.validate()) << what;
        expectValidBasis(CameraFrame(camera, 64, 48), what);
    }
    // theta 90, phi 0 looks down -z with +y up and +x to the right (camera.h).
    const CameraFrame front(Camera::fromAngles(90, 0), 32, 32);
    expectNear(front.forward(), {0, 0, -1}, 1e-12, "forward");
    expectNear(front.right(), {1, 0, 0}, 1e-12, "right");
    expectNear(front.upVector(), {0, 1, 0}, 1e-12, "up");
    // Radius and field of view are passed through.
    const Camera far = Camera::fromAngles(90, 90, 4.0, 30.0);
    expectNear(far.eye, {4, 0, 0}, 1e-12, "radius 4");
    EXPECT_EQ(far.fovYDeg, 30.0);
}

TEST(Camera, PoleUpVectorIsValidAndContinuous)
{
    // At the poles the world up is parallel to the view; the image basis must still be valid and
    // match the limit of views approaching the pole along the same azimuth.
    for (double phi : {0.0, 45.0, 130.0, -100.0}) {
        for (double pole : {0.0, 180.0}) {
            const std::string what = "pole " + std::to_string(pole) + " phi " + std::to_string(phi);
            const Camera atPole = Camera::fromAngles(pole, phi);
            ASSERT_NO_THROW(atPole.validate()) << what;
            const CameraFrame frame(atPole, 32, 32);
            expectValidBasis(frame, what);
            const double near = pole == 0.0 ? 1e-4 : 180.0 - 1e-4;
            const CameraFrame nearby(Camera::fromAngles(near, phi), 32, 32);
            expectNear(frame.upVector(), nearby.upVector(), 1e-4, what + " up continuity");
            expectNear(frame.right(), nearby.right(), 1e-4, what + " right continuity");
        }
    }
}

TEST(Camera, ProjectInvertsRayForBothProjections)
{
    Camera camera;
    camera.eye = {0.7, 1.1, 2.2};
    camera.target = {0.1, -0.2, 0.05};
    camera.up = {0.1, 1.0, 0.0};
    for (bool orthographic : {false, true}) {
        camera.orthographic = orthographic;
        camera.fovYDeg = 50.0;
        camera.orthoHalfHeight = 1.3;
        const CameraFrame frame(camera, 96, 64);
        for (double x : {0.0, 0.5, 17.25, 48.0, 95.5, 96.0})
            for (double y : {0.0, 0.5, 31.75, 63.9, 64.0})
                for (double t : {0.3, 1.0, 2.5, 7.0}) {
                    const CameraRay ray = frame.ray(x, y);
                    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
                    const glm::dvec2 pixel = frame.project(ray.origin + t * ray.direction);
                    EXPECT_NEAR(pixel.x, x, 1e-9) << "ortho " << orthographic << " t " << t;
                    EXPECT_NEAR(pixel.y, y, 1e-9) << "ortho " << orthographic << " t " << t;
                }
        // The image centre looks at the target; pixel row 0 is the top (up), column 0 the left.
        const glm::dvec2 centre = frame.project(camera.target);
        EXPECT_NEAR(centre.x, 48.0, 1e-9);
        EXPECT_NEAR(centre.y, 32.0, 1e-9);
        const glm::dvec2 above = frame.project(camera.target + 0.1 * frame.upVector());
        const glm::dvec2 right = frame.project(camera.target + 0.1 * frame.right());
        EXPECT_LT(above.y, 32.0);
        EXPECT_GT(right.x, 48.0);
        if (orthographic) {
            // Orthographic rays are parallel to the view and their origins span the view height.
            EXPECT_LT(glm::length(frame.ray(3.0, 7.0).direction - frame.forward()), 1e-12);
            const double height = glm::length(frame.ray(10.0, 0.0).origin - frame.ray(10.0, 64.0).origin);
            EXPECT_NEAR(height, 2.0 * camera.orthoHalfHeight, 1e-12);
        } else {
            // The top and bottom edge rays span the vertical field of view.
            const double angle = std::acos(glm::dot(frame.ray(48.0, 0.0).direction, frame.ray(48.0, 64.0).direction));
            EXPECT_NEAR(angle * 180.0 / M_PI, camera.fovYDeg, 1e-9);
        }
    }
}

// A window centre shifts the image on the image plane: the same world point moves by the shift in
// image half-heights, project still inverts ray, and the view axis leaves the image centre.
TEST(Camera, WindowCentreShiftsTheImageOnTheImagePlane)
{
    for (bool orthographic : {false, true}) {
        Camera camera = Camera::fromAngles(70.0, 25.0, kCameraDistance, 50.0);
        camera.orthographic = orthographic;
        const CameraFrame centred(camera, 80, 60);
        camera.windowCentre = {0.2, -0.1};
        const CameraFrame shifted(camera, 80, 60);
        const glm::dvec3 point(0.3, -0.4, 0.2);
        const double pixelsPerUnit = 30.0 / shifted.imagePlaneHalfHeight();
        EXPECT_NEAR(shifted.project(point).x, centred.project(point).x - 0.2 * pixelsPerUnit, 1e-9);
        EXPECT_NEAR(shifted.project(point).y, centred.project(point).y - 0.1 * pixelsPerUnit, 1e-9);
        EXPECT_EQ(shifted.imagePlane(point), centred.imagePlane(point)) << "the image plane itself stays";
        for (double x : {0.0, 13.5, 80.0})
            for (double y : {0.0, 41.25, 60.0}) {
                const CameraRay ray = shifted.ray(x, y);
                const glm::dvec2 pixel = shifted.project(ray.origin + 1.7 * ray.direction);
                EXPECT_NEAR(pixel.x, x, 1e-9);
                EXPECT_NEAR(pixel.y, y, 1e-9);
            }
    }
}

TEST(Camera, AnglesInvertFromAngles)
{
    for (double theta = 5.0; theta < 180.0; theta += 17.5)
        for (double phi = -175.0; phi <= 180.0; phi += 25.0) {
            const glm::dvec2 angles = Camera::fromAngles(theta, phi, 1.7).angles();
            EXPECT_NEAR(angles.x, theta, 1e-9) << theta << " " << phi;
            EXPECT_NEAR(angles.y, phi, 1e-9) << theta << " " << phi;
        }
    // Azimuths outside (-180, 180] come back wrapped; the poles keep their polar angle.
    EXPECT_NEAR(Camera::fromAngles(60.0, 270.0).angles().y, -90.0, 1e-9);
    EXPECT_NEAR(Camera::fromAngles(0.0, 30.0).angles().x, 0.0, 1e-9);
    EXPECT_NEAR(Camera::fromAngles(180.0, 30.0).angles().x, 180.0, 1e-9);
    // Angles are measured around the target, not the origin.
    Camera shifted = Camera::fromAngles(70.0, 40.0);
    shifted.eye += glm::dvec3(0.3, -0.2, 0.5);
    shifted.target += glm::dvec3(0.3, -0.2, 0.5);
    EXPECT_NEAR(shifted.angles().x, 70.0, 1e-9);
    EXPECT_NEAR(shifted.angles().y, 40.0, 1e-9);
}

TEST(Camera, JsonRoundTrip)
{
    test::TempDir dir;
    for (bool orthographic : {false, true}) {
        Camera camera;
        camera.eye = {0.123456789012345, -2.25, 1.0 / 3.0};
        camera.target = {0.1, 0.2, -0.3};
        camera.up = {0.0, 0.6, 0.8};
        camera.fovYDeg = 41.3;
        camera.orthographic = orthographic;
        camera.orthoHalfHeight = 0.95;
        camera.windowCentre = {0.0123456789, -0.75};
        const std::string path = dir.file(orthographic ? "ortho.json" : "persp.json");
        writeCameraJson(camera, path);
        const Camera read = readCameraJson(path);
        EXPECT_EQ(read.eye, camera.eye);
        EXPECT_EQ(read.target, camera.target);
        EXPECT_EQ(read.up, camera.up);
        EXPECT_EQ(read.fovYDeg, camera.fovYDeg);
        EXPECT_EQ(read.orthographic, camera.orthographic);
        EXPECT_EQ(read.orthoHalfHeight, camera.orthoHalfHeight);
        EXPECT_EQ(read.windowCentre, camera.windowCentre);
    }
    // Missing keys but the eye keep their defaults.
    test::writeFile(dir.file("partial.json"), "{\"eye\": [1, 2, 3]}");
    const Camera partial = readCameraJson(dir.file("partial.json"));
    EXPECT_EQ(partial.eye, glm::dvec3(1, 2, 3));
    EXPECT_EQ(partial.target, Camera().target);
    EXPECT_EQ(partial.fovYDeg, kDefaultFovYDeg);
}

/// Expects readCameraJson(path) to throw InputError whose message names the path.
void expectBadCameraFile(const std::string& path)
{
    try {
        readCameraJson(path);
        FAIL() << "expected InputError for " << path;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
}

TEST(Camera, FarButRepresentableCamerasAreValid)
{
    Camera camera;
    camera.eye = {kMaxCameraCoordinate, 0.0, 0.0};
    camera.fovYDeg = 1e-4;
    EXPECT_NO_THROW(camera.validate());
    camera.eye.x = std::nextafter(kMaxCameraCoordinate, 2.0 * kMaxCameraCoordinate);
    EXPECT_THROW(camera.validate(), ValueError);
}

TEST(Camera, BadJsonThrowsInputErrorNamingThePath)
{
    test::TempDir dir;
    const std::vector<std::pair<std::string, std::string>> files = {
        {"truncated.json", "{\"eye\": [0, 0, 2.5], \"target\": [0, 0"},
        {"garbage.json", "this is not json"},
        {"array.json", "[1, 2, 3]"},
        {"empty.json", "{}"},
        {"no_eye.json", "{\"target\": [0, 0, 0], \"fov_y_deg\": 40}"},
        {"view_file.json", "{\"inversevis_view\": 1, \"camera\": {\"eye\": [0, 0, 2.5]}}"},
        {"short_vector.json", "{\"eye\": [0, 0]}"},
        {"string_value.json", "{\"fov_y_deg\": \"wide\"}"},
        {"eye_is_target.json", "{\"eye\": [0, 0, 0], \"target\": [0, 0, 0]}"},
        {"bad_fov.json", "{\"fov_y_deg\": 180}"},
        {"short_window.json", "{\"window_centre\": [0.1]}"},
        {"text_window.json", "{\"window_centre\": [\"left\", 0]}"},
        {"huge_window.json", "{\"window_centre\": [1e400, 0]}"},
        // Beyond what single-precision rays represent (Embree asserted on an eye at 1e20).
        {"far_eye.json", "{\"eye\": [1e20, 0, 0], \"fov_y_deg\": 30}"},
        {"far_target.json", "{\"eye\": [0, 0, 2.5], \"target\": [0, 2e6, 0]}"},
        {"wide_ortho.json", "{\"eye\": [0, 0, 2.5], \"orthographic\": true, \"ortho_half_height\": 1e30}"},
        {"far_window.json", "{\"eye\": [0, 0, 2.5], \"window_centre\": [0, -3e6]}"}};
    for (const auto& [name, text] : files) {
        test::writeFile(dir.file(name), text);
        expectBadCameraFile(dir.file(name));
    }
    expectBadCameraFile(dir.file("missing.json"));
}

}  // namespace
}  // namespace ivis::core
