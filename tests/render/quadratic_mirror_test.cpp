// The quadratic mirror against its definition in eye space (quadratic_mirror.h): the hit lies on the
// camera ray and on z = zm + w1 x^2 + w2 y^2 + w3 xy + w4 x + w5 y, the normal is the height field's.
#include "render/scene_fixture.h"

#include <ivis/core/camera.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/mirror_method.h>
#include <ivis/render/quadratic_mirror.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace ivis::render {
namespace {

/// Eye-space coordinates of a world point: x right, y up, z toward the viewer, camera at the origin.
glm::dvec3 eyeFromWorldPoint(const core::CameraFrame& frame, const glm::dvec3& world)
{
    const glm::dvec3 d = world - frame.camera().eye;
    return {glm::dot(d, frame.right()), glm::dot(d, frame.upVector()), -glm::dot(d, frame.forward())};
}

/// World direction of an eye-space direction.
glm::dvec3 worldFromEyeDirection(const core::CameraFrame& frame, const glm::dvec3& v)
{
    return v.x * frame.right() + v.y * frame.upVector() - v.z * frame.forward();
}

double mirrorHeight(const std::array<float, 5>& w, double zm, double x, double y)
{
    return zm + w[0] * x * x + w[1] * y * y + w[2] * x * y + w[3] * x + w[4] * y;
}

std::vector<core::Camera> cameras()
{
    std::vector<core::Camera> result = {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(35, 140),
                                        core::Camera::fromAngles(150, -60, 3.2, 50.0)};
    core::Camera offCentre = core::Camera::fromAngles(70, 20);
    offCentre.target = {0.2, -0.1, 0.3};  // zm follows the eye-target distance, not |eye|
    result.push_back(offCentre);
    core::Camera ortho = core::Camera::fromAngles(110, 200);
    ortho.orthographic = true;
    result.push_back(ortho);
    return result;
}

double cameraDistance(const core::Camera& camera) { return glm::length(camera.target - camera.eye); }

TEST(QuadraticMirror, FlatMirrorFacesTheCameraAtTheDocumentedDepth)
{
    for (const core::Camera& camera : cameras())
        for (float behind : {1.0f, 0.4f, 2.0f}) {
            const core::CameraFrame frame(camera, 48, 40);
            MirrorParams params;
            params.w = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
            params.distanceBehind = behind;
            const double depth = cameraDistance(camera) + behind;
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 48; ++x) {
                    const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
                    MirrorHit hit;
                    // Every camera ray points away from the viewer, so it meets the plane.
                    ASSERT_TRUE(intersectMirror(frame, ray, params, hit)) << x << "," << y;
                    EXPECT_LT(glm::length(glm::dvec3(hit.normal) + frame.forward()), 1e-6);
                    const glm::dvec3 m = eyeFromWorldPoint(frame, glm::dvec3(hit.point));
                    EXPECT_NEAR(-m.z, depth, 1e-5 * depth);
                    // On the camera ray, in front of the camera.
                    const glm::dvec3 offset = glm::dvec3(hit.point) - ray.origin;
                    EXPECT_LT(glm::length(glm::cross(offset, ray.direction)), 1e-5);
                    EXPECT_GT(glm::dot(offset, ray.direction), 0.0);
                }
        }
}

/// Hit and miss counts of one mirror over a 40x40 image.
struct HitCounts {
    int hits = 0;
    int originAbove = 0;  ///< pixels whose ray starts on the viewer's side of the mirror
};

/// Checks every pixel of a 40x40 image against the height field and its normal: hits lie on the
/// camera ray and the mirror with the height field's normal, and are the FIRST crossing; misses
/// never cross the mirror.
HitCounts expectHitsOnHeightField(const core::Camera& camera, const MirrorParams& params, const std::string& name)
{
    const core::CameraFrame frame(camera, 40, 40);
    const double zm = -cameraDistance(camera) - params.distanceBehind;
    const auto& w = params.w;
    HitCounts counts;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
            const std::string where = name + " pixel " + std::to_string(x) + "," + std::to_string(y);
            const glm::dvec3 o = eyeFromWorldPoint(frame, ray.origin);
            const bool above = o.z > mirrorHeight(w, zm, o.x, o.y);
            counts.originAbove += above;
            MirrorHit hit;
            if (!intersectMirror(frame, ray, params, hit)) {
                if (!above) continue;
                int crossing = -1;
                for (int k = 0; k <= 400 && crossing < 0; ++k) {
                    const glm::dvec3 q = eyeFromWorldPoint(frame, ray.origin + (0.05 * k) * ray.direction);
                    if (q.z <= mirrorHeight(w, zm, q.x, q.y)) crossing = k;
                }
                EXPECT_LT(crossing, 0) << where << ": a miss whose ray crosses the mirror at t = " << 0.05 * crossing;
                continue;
            }
            ++counts.hits;
            const glm::dvec3 m = eyeFromWorldPoint(frame, glm::dvec3(hit.point));
            EXPECT_NEAR(m.z, mirrorHeight(w, zm, m.x, m.y), 1e-5) << where;
            const glm::dvec3 expected = worldFromEyeDirection(
                frame, glm::normalize(glm::dvec3(-2.0 * w[0] * m.x - w[2] * m.y - w[3],
                                                 -2.0 * w[1] * m.y - w[2] * m.x - w[4], 1.0)));
            EXPECT_LT(glm::length(glm::dvec3(hit.normal) - expected), 1e-5) << where;
            // On the camera ray, in front of the camera, and the FIRST crossing: every point of the
            // ray before it lies on the camera's side (z above the mirror).
            const glm::dvec3 offset = glm::dvec3(hit.point) - ray.origin;
            EXPECT_LT(glm::length(glm::cross(offset, ray.direction)), 1e-5) << where;
            const double t = glm::dot(offset, ray.direction);
            EXPECT_GT(t, 0.0) << where;
            EXPECT_TRUE(above) << where;
            for (int k = 0; k < 50; ++k) {
                const glm::dvec3 q = eyeFromWorldPoint(frame, ray.origin + (t * k / 50.0) * ray.direction);
                EXPECT_GT(q.z, mirrorHeight(w, zm, q.x, q.y) - 1e-9) << where << " sample " << k;
            }
        }
    return counts;
}

TEST(QuadraticMirror, CurvedMirrorHitsSatisfyTheHeightField)
{
    for (const core::Camera& camera : cameras()) {
        const std::string kind = camera.orthographic ? "ortho " : "persp ";
        MirrorParams params;
        // A bowl opening toward the viewer: every ray starting on the viewer's side meets it
        // (perspective rays all start at the eye, above the apex).
        params.w = {0.3f, 0.3f, 0.0f, 0.0f, 0.0f};
        HitCounts counts = expectHitsOnHeightField(camera, params, kind + "bowl");
        EXPECT_EQ(counts.hits, counts.originAbove);
        if (!camera.orthographic) { EXPECT_EQ(counts.hits, 40 * 40); }
        params.w = {0.8f, 0.8f, 0.0f, 0.0f, 0.0f};
        params.distanceBehind = 0.5f;
        counts = expectHitsOnHeightField(camera, params, kind + "steep bowl");
        EXPECT_EQ(counts.hits, counts.originAbove);
        if (!camera.orthographic) { EXPECT_EQ(counts.hits, 40 * 40); }
        params.w = {0.3f, 0.5f, 0.2f, -0.1f, 0.15f};
        params.distanceBehind = 1.0f;
        EXPECT_GT(expectHitsOnHeightField(camera, params, kind + "general").hits, 0);
        // A dome bending away: outer rays may pass it; those that meet it take the nearer root.
        params.w = {-0.2f, -0.2f, 0.0f, 0.0f, 0.0f};
        EXPECT_GT(expectHitsOnHeightField(camera, params, kind + "dome").hits, 0);
    }
}

TEST(QuadraticMirror, BowlNormalsTiltTowardTheAxis)
{
    // w1 = w2 > 0: at eye-space (x, y) the normal's in-plane part is -2 w (x, y): toward the axis,
    // and pixels on opposite sides of the centre tilt opposite ways.
    const core::Camera camera = core::Camera::fromAngles(90, 0);
    const core::CameraFrame frame(camera, 64, 64);
    MirrorParams params;
    params.w = {0.3f, 0.3f, 0.0f, 0.0f, 0.0f};
    MirrorHit left, right, top;
    ASSERT_TRUE(intersectMirror(frame, frame.ray(8.0, 32.0), params, left));
    ASSERT_TRUE(intersectMirror(frame, frame.ray(56.0, 32.0), params, right));
    ASSERT_TRUE(intersectMirror(frame, frame.ray(32.0, 4.0), params, top));
    EXPECT_GT(glm::dot(glm::dvec3(left.normal), frame.right()), 0.05);
    EXPECT_LT(glm::dot(glm::dvec3(right.normal), frame.right()), -0.05);
    EXPECT_LT(glm::dot(glm::dvec3(top.normal), frame.upVector()), -0.05);
    // Symmetric pixels give mirror-image normals.
    EXPECT_NEAR(glm::dot(glm::dvec3(left.normal), frame.right()), -glm::dot(glm::dvec3(right.normal), frame.right()),
                1e-5);
}

/// Brute force of mirrorFootprint: the image-plane extent of the pixel centres of a @a size^2
/// picture at the widest framed field of view whose mirror ray lands (the method's own sphere tracing).
PictureExtent landedReach(const RenderScene& scene, const core::Camera& camera, const MethodPtr& mirror, int size)
{
    core::Camera widest = camera;
    widest.fovYDeg = kMaxFramedFovYDeg;
    const core::CameraFrame frame(widest, size, size);
    const std::unique_ptr<IndirectMap> map = mirror->indirectMap(scene, frame);
    auto sampler = scene.distance().sampler();
    PictureExtent reach = PictureExtent::empty();
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            if (map->map(x + 0.5, y + 0.5, sampler).region == Region::Indirect) {
                const core::CameraRay ray = frame.ray(x + 0.5, y + 0.5);
                const glm::dvec2 s = frame.imagePlane(ray.origin + ray.direction);
                reach.lo = glm::min(reach.lo, s);
                reach.hi = glm::max(reach.hi, s);
            }
    return reach;
}

// The footprint's reach on each side is that of the pixels whose mirror ray lands, found by brute force at
// 500 x 500 over the widest framed image (pixel 0.015 on the image plane): within three such
// pixels either way (the footprint adds one fine cell; a landing also counts a ray that passes
// within half a voxel of the surface, which the footprint's ray casts do not).
TEST(QuadraticMirror, FootprintReachesAsFarAsTheLandingRays)
{
    const std::vector<std::pair<const test::SceneFixture*, std::string>> scenes = {{&test::sphereScene(), "sphere"},
                                                                                   {&test::vesselScene(), "tree"}};
    const std::vector<std::vector<float>> ws = {{0.3f, 0.3f, 0.0f, 0.0f, 0.0f}, {1.0f, 0.4f, 0.3f, 0.2f, -0.3f}};
    constexpr int kSize = 500;
    const double pixel = 2.0 * std::tan(0.5 * kMaxFramedFovYDeg * M_PI / 180.0) / kSize;
    for (const auto& [fixture, name] : scenes)
        for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(50, 120)})
            for (const std::vector<float>& w : ws) {
                const MethodPtr mirror = makeMethod("mirror", {{"mirror_w", w}});
                const auto& params = dynamic_cast<const MirrorMethod&>(*mirror).params();
                const RenderScene& scene = *fixture->scene;
                const PictureExtent footprint = mirrorFootprint(camera, params, scene.bvh(), core::bounds(scene.mesh()));
                const PictureExtent brute = landedReach(scene, camera, mirror, kSize);
                ASSERT_GT(brute.hi.x - brute.lo.x, 0.1) << name;
                for (int axis = 0; axis < 2; ++axis) {
                    EXPECT_NEAR(footprint.lo[axis], brute.lo[axis], 3.0 * pixel) << name << " w1 " << w[0] << " axis " << axis;
                    EXPECT_NEAR(footprint.hi[axis], brute.hi[axis], 3.0 * pixel) << name << " w1 " << w[0] << " axis " << axis;
                }
            }
}

}  // namespace
}  // namespace ivis::render
