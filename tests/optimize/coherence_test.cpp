// Mapping coherence on hand-made P layers with known tears, and on a render's layers.
#include "render/scene_fixture.h"

#include <ivis/core/errors.h>
#include <ivis/optimize/coherence.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <random>

namespace ivis::optimize {
namespace {

TEST(MappingCoherence, CountsTheTornPairsOfAHandMadeLayer)
{
    // 5 x 4 pixels; column 4 is background. Columns 0-1 show points near x = 0, columns 2-3 near
    // x = 1: the 4 horizontal pairs across columns 1|2 are torn.
    //   a a b b .
    //   a a b b .
    //   a a b b .
    //   a a b b .
    const int width = 5, height = 4;
    std::vector<char> indirect(width * height, 0);
    std::vector<glm::vec3> points(width * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < 4; ++x) {
            indirect[y * width + x] = 1;
            points[y * width + x] = glm::vec3(x < 2 ? 0.01f * x : 1.0f + 0.01f * x, 0.02f * y, 0.0f);
        }
    const Coherence c = mappingCoherence(indirect, points, width, height);
    EXPECT_EQ(c.pairs, 4u * 3u + 3u * 4u);  // 3 horizontal pairs per row, 3 vertical per column
    EXPECT_EQ(c.coherent, c.pairs - 4u);
    EXPECT_DOUBLE_EQ(c.value(), 20.0 / 24.0);
    EXPECT_DOUBLE_EQ(mappingCoherence(std::vector<char>(4, 0), std::vector<glm::vec3>(4), 2, 2).value(), 1.0)
        << "no pair, no tear";
    points[0] = glm::vec3(0.0f, 0.0f, 0.09f);  // within 0.1 of its neighbours (0.01, 0, 0) and (0, 0.02, 0)
    EXPECT_EQ(mappingCoherence(indirect, points, width, height).coherent, c.coherent);
    points[0] = glm::vec3(0.0f, 0.0f, 0.2f);  // now beyond: two more torn pairs
    std::vector<char> torn;
    EXPECT_EQ(mappingCoherence(indirect, points, width, height, kCoherenceDistance, &torn).coherent, c.coherent - 2u);
    // With stride 2 only pixels (0|2|4, 0|2) and their right and lower neighbours count: 8 pairs
    // (column 4 is background), 2 of them torn by pixel 0, none across columns 1|2.
    const Coherence sampled = mappingCoherence(indirect, points, width, height, kCoherenceDistance, nullptr, 2);
    EXPECT_EQ(sampled.pairs, 8u);
    EXPECT_EQ(sampled.coherent, 6u);
    EXPECT_THROW(mappingCoherence(indirect, points, width, height, kCoherenceDistance, nullptr, 0), ValueError);
    // The tears' pixels: columns 1 and 2 of every row, pixel 0 and its two neighbours.
    ASSERT_EQ(torn.size(), std::size_t(width * height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool expected = x == 1 || x == 2 || (y == 0 && x == 0) || (y == 1 && x == 0);
            EXPECT_EQ(bool(torn[y * width + x]), expected) << x << ", " << y;
        }
    // The tear map shows those pixels red and the others grey.
    const core::Image picture(width, height, glm::vec4(0.0f, 0.5f, 1.0f, 1.0f));
    const core::Image map = tearMap(picture, torn);
    EXPECT_EQ(map.at(1, 3), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    const glm::vec4 grey = map.at(3, 3);
    EXPECT_EQ(grey.r, grey.g);
    EXPECT_EQ(grey.g, grey.b);
    EXPECT_THROW(tearMap(picture, std::vector<char>(3, 0)), ValueError);
}

TEST(MappingCoherence, IsTheBruteForceCountOnALargeLayerAtEveryStride)
{
    // A layer far larger than one row block: a random walk of points with jumps (tears) and holes
    // (background), counted pair by pair here and by the measure in parallel.
    const int width = 301, height = 257;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<char> indirect(std::size_t(width) * height);
    std::vector<glm::vec3> points(indirect.size());
    core::ImageLayers layers(width, height);
    core::Channel& region = layers.add("region");
    core::Channel &px = layers.add("P.X"), &py = layers.add("P.Y"), &pz = layers.add("P.Z");
    for (std::size_t i = 0; i < indirect.size(); ++i) {
        indirect[i] = unit(random) < 0.85f;
        const float jump = unit(random) < 0.05f ? 0.5f : 0.03f;
        points[i] = glm::vec3(unit(random), unit(random), unit(random)) * jump + float(i % width) * 0.01f;
        region[i] = float(indirect[i] ? render::Region::Indirect : render::Region::Background);
        px[i] = points[i].x, py[i] = points[i].y, pz[i] = points[i].z;
    }
    for (const int stride : {1, 2, 3, 7}) {
        Coherence expected;
        std::vector<char> expectedTorn(indirect.size(), 0);
        auto pair = [&](std::size_t a, std::size_t b) {
            if (!indirect[a] || !indirect[b]) return;
            ++expected.pairs;
            if (glm::distance(glm::dvec3(points[a]), glm::dvec3(points[b])) <= kCoherenceDistance)
                ++expected.coherent;
            else
                expectedTorn[a] = expectedTorn[b] = 1;
        };
        for (int y = 0; y < height; y += stride)
            for (int x = 0; x < width; x += stride) {
                const std::size_t i = std::size_t(y) * width + x;
                if (x + 1 < width) pair(i, i + 1);
                if (y + 1 < height) pair(i, i + width);
            }
        std::vector<char> torn;
        const Coherence c = mappingCoherence(indirect, points, width, height, kCoherenceDistance, &torn, stride);
        EXPECT_EQ(c.pairs, expected.pairs) << "stride " << stride;
        EXPECT_EQ(c.coherent, expected.coherent) << "stride " << stride;
        EXPECT_GT(c.pairs - c.coherent, 100u) << "the layer must tear";
        ASSERT_EQ(torn.size(), expectedTorn.size());
        for (std::size_t i = 0; i < torn.size(); ++i)
            ASSERT_EQ(bool(torn[i]), bool(expectedTorn[i])) << "stride " << stride << ", pixel " << i;
        if (stride != 1) continue;
        std::vector<char> tornOfLayers;
        const Coherence fromLayers = mappingCoherence(layers, kCoherenceDistance, &tornOfLayers);
        EXPECT_EQ(fromLayers.pairs, expected.pairs);
        EXPECT_EQ(fromLayers.coherent, expected.coherent);
        EXPECT_EQ(tornOfLayers, torn);
    }
}

TEST(MappingCoherence, OfARenderEqualsTheMeasureOfItsView)
{
    const auto& fixture = test::vesselScene();
    render::RenderOptions options;
    options.width = options.height = 96;
    options.method = render::makeMethod("inversevis");
    const core::Camera camera = core::Camera::fromAngles(90.0, 0.0);
    const render::RenderResult result = render::renderImage(*fixture.scene, camera, options);
    const Coherence fromLayers = mappingCoherence(result.layers);
    const Coherence direct = measureCoherence(*fixture.scene, camera, options.method, 96);
    EXPECT_GT(fromLayers.pairs, 1000u);
    EXPECT_EQ(fromLayers.pairs, direct.pairs);
    EXPECT_EQ(fromLayers.coherent, direct.coherent);
}

}  // namespace
}  // namespace ivis::optimize
