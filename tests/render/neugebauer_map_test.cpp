// Ring map geometry (neugebauer_map.h) recomputed by hand: radii from the projected vertices, ray
// directions across the ring (toward the viewer inside, away outside), and the back disc.
#include <ivis/core/camera.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/render/framing.h>
#include <ivis/render/neugebauer_map.h>
#include <ivis/render/neugebauer_method.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ivis::render {
namespace {

const core::TriangleMesh& sphereMesh()
{
    static const core::SurfaceField field = core::makeSphere(3);
    return field.mesh;
}

const core::TriangleMesh& treeMesh()
{
    static const core::SurfaceField field = core::makeVesselTree(40);
    return field.mesh;
}

/// r1 by hand: largest distance of a projected vertex from the projected centre, plus the gap.
double innerRadiusByHand(const core::CameraFrame& frame, const core::TriangleMesh& mesh, const RingParams& params)
{
    const glm::dvec2 c = frame.project(glm::dvec3(params.centre));
    double largest = 0.0;
    for (const glm::vec3& p : mesh.positions) {
        const glm::dvec2 q = frame.project(glm::dvec3(p));
        largest = std::max(largest, std::hypot(q.x - c.x, q.y - c.y));
    }
    return largest + params.silhouetteGap * 0.5 * frame.height();
}

/// In-plane unit direction of a screen offset (pixel y grows downward).
glm::dvec3 inPlane(const core::CameraFrame& frame, const glm::dvec2& offset)
{
    return glm::normalize(offset.x * frame.right() - offset.y * frame.upVector());
}

struct RingCase {
    core::Camera camera;
    int width, height;
    RingParams params;
    const core::TriangleMesh* mesh;
    std::string name;
};

std::vector<RingCase> setups()
{
    std::vector<RingCase> result;
    result.push_back({core::Camera::fromAngles(90, 0), 96, 96, RingParams{}, &sphereMesh(), "sphere default"});
    RingParams custom;
    custom.centre = {0.1f, -0.2f, 0.05f};
    custom.ringWidth = 0.25f;
    custom.silhouetteGap = 0.05f;
    custom.backRadius = 0.2f;
    result.push_back({core::Camera::fromAngles(60, 30), 128, 96, custom, &sphereMesh(), "sphere custom 128x96"});
    result.push_back({core::Camera::fromAngles(90, 0), 128, 128, RingParams{}, &treeMesh(), "tree default"});
    result.push_back({core::Camera::fromAngles(120, -70), 96, 128, custom, &treeMesh(), "tree custom 96x128"});
    return result;
}

TEST(NeugebauerMap, RingRadiiFollowTheProjectedSilhouette)
{
    for (const RingCase& s : setups()) {
        const core::CameraFrame frame(s.camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        const double halfHeight = 0.5 * s.height;
        const glm::dvec2 c = frame.project(glm::dvec3(s.params.centre));
        EXPECT_NEAR(layout.centre.x, c.x, 1e-9) << s.name;
        EXPECT_NEAR(layout.centre.y, c.y, 1e-9) << s.name;
        const double r1 = innerRadiusByHand(frame, *s.mesh, s.params);
        EXPECT_NEAR(layout.innerRadius, r1, 1e-6) << s.name;
        EXPECT_NEAR(layout.outerRadius, r1 + s.params.ringWidth * halfHeight, 1e-6) << s.name;
        EXPECT_NEAR(layout.backRadius, s.params.backRadius * halfHeight, 1e-9) << s.name;
        // The ring lies outside the silhouette: every vertex projects inside r1.
        for (const glm::vec3& p : s.mesh->positions)
            ASSERT_LT(glm::length(frame.project(glm::dvec3(p)) - c), layout.innerRadius) << s.name;
    }
    // For a unit sphere seen head-on the silhouette radius is analytic: the tangent cone's
    // half-angle asin(1/2.5); the mesh's vertices lie on the sphere, so r1 - gap is just below it.
    const core::CameraFrame frame(core::Camera::fromAngles(90, 0), 96, 96);
    const RingLayout layout = layoutRings(frame, sphereMesh(), RingParams{});
    const double tanHalf = std::tan(0.5 * core::kDefaultFovYDeg * M_PI / 180.0);
    const double silhouette = std::tan(std::asin(1.0 / 2.5)) / tanHalf * 48.0;
    EXPECT_NEAR(layout.innerRadius - 0.02 * 48.0, silhouette, 0.02 * silhouette);
    EXPECT_LE(layout.innerRadius - 0.02 * 48.0, silhouette + 1e-6);
}

// Framed by ringExtent, the outer ring touches the margin on the axis that limits it and stays
// inside it on the other, for every set-up (off-centre ring centres and non-square images included).
TEST(NeugebauerMap, FramedRingsTouchTheMarginAndNoMore)
{
    for (const RingCase& s : setups()) {
        const double aspect = double(s.width) / s.height;
        const core::Camera camera = fitCamera(s.camera, ringExtent(s.camera, *s.mesh, s.params), aspect);
        const core::CameraFrame frame(camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        const double halfHeight = 0.5 * s.height;
        // Reach of the outer circle from the image centre, per axis, over the room within the margin.
        const double x = (std::abs(layout.centre.x - 0.5 * s.width) + layout.outerRadius) / halfHeight;
        const double y = (std::abs(layout.centre.y - 0.5 * s.height) + layout.outerRadius) / halfHeight;
        const double used = std::max(x / (aspect - kFramingMargin), y / (1.0 - kFramingMargin));
        EXPECT_NEAR(used, 1.0, 1e-6) << s.name;
    }
}

TEST(NeugebauerMap, RingDirectionsSweepFromTowardTheViewerToAway)
{
    for (const RingCase& s : setups()) {
        const core::CameraFrame frame(s.camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        // The edges themselves, pulled in by 1e-9 pixels against rounding of centre + r * unit.
        const double r1 = layout.innerRadius + 1e-9, r2 = layout.outerRadius - 1e-9, mid = 0.5 * (r1 + r2);
        const glm::dvec3 n = frame.forward();
        int tested = 0;
        for (int k = 0; k < 24; ++k) {
            const double angle = 2.0 * M_PI * (k + 0.3) / 24.0;
            const glm::dvec2 unit(std::cos(angle), std::sin(angle));
            // Skip directions whose ring pixels fall inside the back disc (the disc wins there).
            bool inDisc = false;
            for (double r : {r1, mid, r2})
                inDisc |= glm::length(layout.centre + r * unit - layout.backCentre) <= layout.backRadius;
            if (inDisc) continue;
            ++tested;
            const glm::dvec3 u = inPlane(frame, unit);
            for (double r : {r1, 0.5 * (r1 + mid), mid, 0.5 * (mid + r2), r2}) {
                const glm::dvec2 pixel = layout.centre + r * unit;
                glm::vec3 direction;
                ASSERT_TRUE(ringRayDirection(layout, frame, pixel, direction)) << s.name << " r " << r;
                const glm::dvec3 d(direction);
                const glm::dvec3 expected =
                    glm::normalize(u + (2.0 * r / (layout.innerRadius + layout.outerRadius) - 1.0) * n);
                EXPECT_LT(glm::length(d - expected), 1e-5) << s.name << " r " << r;
                EXPECT_NEAR(glm::length(d), 1.0, 1e-6);
                const double along = glm::dot(d, n);
                if (r == mid) { EXPECT_NEAR(along, 0.0, 1e-6) << s.name; }
                if (r == r1) { EXPECT_LT(along, -0.01) << s.name << ": inner edge must look toward the viewer"; }
                if (r == r2) { EXPECT_GT(along, 0.01) << s.name << ": outer edge must look away"; }
                // The in-plane part points the way the pixel lies from the centre on screen.
                EXPECT_GT(glm::dot(d, u), 0.5) << s.name;
            }
            // Just inside r1 and just outside r2 (and off the disc): no map ray.
            for (double r : {r1 - 0.5, r2 + 0.5}) {
                const glm::dvec2 pixel = layout.centre + r * unit;
                if (glm::length(pixel - layout.backCentre) <= layout.backRadius) continue;
                glm::vec3 direction;
                EXPECT_FALSE(ringRayDirection(layout, frame, pixel, direction)) << s.name << " r " << r;
            }
        }
        EXPECT_GE(tested, 12) << s.name;
        // Screen right of the centre looks along +right, screen above along +up.
        glm::vec3 toRight, toTop;
        ASSERT_TRUE(ringRayDirection(layout, frame, layout.centre + glm::dvec2(mid, 0.0), toRight));
        EXPECT_GT(glm::dot(glm::dvec3(toRight), frame.right()), 0.99) << s.name;
        if (ringRayDirection(layout, frame, layout.centre + glm::dvec2(0.0, -mid), toTop) &&
            glm::length(layout.centre + glm::dvec2(0.0, -mid) - layout.backCentre) > layout.backRadius) {
            EXPECT_GT(glm::dot(glm::dvec3(toTop), frame.upVector()), 0.99) << s.name;
        }
    }
}

TEST(NeugebauerMap, OnlyRingAndDiscPixelsHaveDirections)
{
    for (const RingCase& s : setups()) {
        const core::CameraFrame frame(s.camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        int ring = 0, disc = 0;
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const glm::dvec2 pixel(x + 0.5, y + 0.5);
                const double r = glm::length(pixel - layout.centre);
                const bool inDisc = glm::length(pixel - layout.backCentre) <= layout.backRadius;
                const bool inRing = r >= layout.innerRadius && r <= layout.outerRadius;
                glm::vec3 direction;
                const bool mapped = ringRayDirection(layout, frame, pixel, direction);
                ASSERT_EQ(mapped, inDisc || inRing) << s.name << " pixel " << x << "," << y << " r " << r;
                ring += inRing && !inDisc;
                disc += inDisc;
            }
        EXPECT_GT(ring, 100) << s.name;
        EXPECT_GT(disc, 50) << s.name;
    }
}

TEST(NeugebauerMap, BackDiscSitsUpperLeftAndLooksAlongTheView)
{
    for (const RingCase& s : setups()) {
        const core::CameraFrame frame(s.camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        const glm::dvec3 n = frame.forward();
        const double R = layout.backRadius;
        // Left half, upper part, entirely inside the image.
        EXPECT_LT(layout.backCentre.x, 0.5 * s.width) << s.name;
        EXPECT_LT(layout.backCentre.y, 0.5 * s.height) << s.name;
        EXPECT_GE(layout.backCentre.x - R, 0.0) << s.name;
        EXPECT_GE(layout.backCentre.y - R, 0.0) << s.name;
        // Centre: straight along the view direction.
        glm::vec3 direction;
        ASSERT_TRUE(ringRayDirection(layout, frame, layout.backCentre, direction));
        EXPECT_NEAR(glm::dot(glm::dvec3(direction), n), 1.0, 1e-6) << s.name;
        // Radius r: angle 90 deg * r / R from the view direction; the rim is perpendicular.
        for (int k = 0; k < 8; ++k) {
            const double angle = 2.0 * M_PI * k / 8.0;
            const glm::dvec2 unit(std::cos(angle), std::sin(angle));
            for (double f : {0.25, 0.5, 0.75, 1.0 - 1e-9}) {
                ASSERT_TRUE(ringRayDirection(layout, frame, layout.backCentre + f * R * unit, direction))
                    << s.name << " f " << f;
                const glm::dvec3 d(direction);
                EXPECT_NEAR(glm::length(d), 1.0, 1e-6);
                EXPECT_NEAR(glm::dot(d, n), std::cos(0.5 * M_PI * f), 1e-5) << s.name << " f " << f;
                // Seen from behind: screen right looks toward the camera's left, screen up stays up.
                const glm::dvec3 side = glm::normalize(d - glm::dot(d, n) * n);
                const glm::dvec3 expected = glm::normalize(-unit.x * frame.right() - unit.y * frame.upVector());
                EXPECT_LT(glm::length(side - expected), 1e-5) << s.name << " angle " << angle;
            }
        }
        ASSERT_TRUE(ringRayDirection(layout, frame, layout.backCentre + glm::dvec2(0.999 * R, 0.0), direction));
        EXPECT_NEAR(glm::dot(glm::dvec3(direction), n), 0.0, 0.01) << s.name;
        EXPECT_LT(glm::dot(glm::dvec3(direction), frame.right()), -0.99) << s.name;
    }
}

// The values the viewer's ring program reads each frame (Method::viewValues) are the CPU's layout.
TEST(NeugebauerMap, ViewValuesAreTheLayoutTheRingMapUses)
{
    for (const RingCase& s : setups()) {
        const core::CameraFrame frame(s.camera, s.width, s.height);
        const RingLayout layout = layoutRings(frame, *s.mesh, s.params);
        const NeugebauerMethod method(s.params);
        const ParameterValues values = method.viewValues(frame, *s.mesh);
        ASSERT_EQ(values.size(), method.info().viewValueKeys.size()) << s.name;
        for (const std::string& key : method.info().viewValueKeys) EXPECT_EQ(values.count(key), 1u) << key;
        EXPECT_EQ(values.at("ring_pixel_centre"), (std::vector<float>{float(layout.centre.x), float(layout.centre.y)}));
        EXPECT_EQ(values.at("ring_inner"), std::vector<float>{float(layout.innerRadius)});
        EXPECT_EQ(values.at("back_centre"),
                  (std::vector<float>{float(layout.backCentre.x), float(layout.backCentre.y)}));
        EXPECT_EQ(values.at("back_radius"), std::vector<float>{float(layout.backRadius)});
    }
}

}  // namespace
}  // namespace ivis::render
