// Hot spots: at the ends of the thinnest principal axis, Gaussian values in [0, 1].
#include <ivis/core/errors.h>
#include <ivis/core/hot_spots.h>
#include <ivis/core/procedural_scenes.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace ivis::core {
namespace {

/// The unit sphere squashed to an ellipsoid with semi-axes 1 (x), 0.6 (y), 0.3 along @a thin
/// (turned from z by 30 degrees about x).
TriangleMesh ellipsoid(glm::vec3& thin)
{
    TriangleMesh mesh = makeSphere(3).mesh;
    const float c = std::cos(0.5236f), s = std::sin(0.5236f);
    thin = glm::vec3(0.0f, -s, c);
    for (glm::vec3& p : mesh.positions) {
        const glm::vec3 q(p.x, 0.6f * p.y, 0.3f * p.z);
        p = glm::vec3(q.x, c * q.y - s * q.z, s * q.y + c * q.z);
    }
    return mesh;
}

TEST(HotSpots, SitAtTheEndsOfTheThinnestAxis)
{
    glm::vec3 thin;
    const TriangleMesh mesh = ellipsoid(thin);
    const HotSpots spots = placeHotSpots(mesh, 2);
    ASSERT_EQ(spots.centres.size(), 2u);
    EXPECT_NEAR(glm::dot(spots.centres[0], thin), -0.3f, 1e-3f);
    EXPECT_NEAR(glm::dot(spots.centres[1], thin), 0.3f, 1e-3f);
    const HotSpots six = placeHotSpots(mesh, 6);
    EXPECT_NEAR(std::abs(six.centres[4].x), 1.0f, 1e-3f) << "the fifth and sixth along the longest axis";
    EXPECT_GT(spots.sigma, 0.0f);

    const std::vector<float> values = hotSpotValues(mesh, spots);
    ASSERT_EQ(values.size(), mesh.positions.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_GE(values[i], 0.0f);
        EXPECT_LE(values[i], 1.0f);
        float nearest = 1e9f;
        for (const glm::vec3& c : spots.centres) nearest = std::min(nearest, glm::length(mesh.positions[i] - c));
        EXPECT_NEAR(values[i], std::exp(-nearest * nearest / (2.0f * spots.sigma * spots.sigma)), 1e-5f);
    }
    EXPECT_THROW(placeHotSpots(mesh, 0), ValueError);
    EXPECT_THROW(placeHotSpots(mesh, 7), ValueError);
}

}  // namespace
}  // namespace ivis::core
