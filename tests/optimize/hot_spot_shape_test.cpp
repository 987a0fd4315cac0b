// Hot spots as one place (docs/measures.md, 4) on hand-painted pictures of the sphere's two hot
// spots: a rectangle's outline is its hull's perimeter, a disc's 4/pi of it; a spot split in two
// keeps the larger part's share; a zigzag band's outline is far longer than its hull's.
#include <ivis/core/hot_spots.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/optimize/hot_spot_shape.h>
#include <ivis/render/pixel_mapping.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace ivis::optimize {
namespace {

/// The unit sphere with two hot spots at opposite ends, and its reveal measure.
struct SpotsOnASphere {
    core::SurfaceField field = core::makeSphere(4);
    core::HotSpots spots = core::placeHotSpots(field.mesh, 2);
    RevealMeasure reveal = [this] {
        field.values = core::hotSpotValues(field.mesh, spots);
        field.name = "hotspots";
        return RevealMeasure(field, core::ScalarRange{0.0f, 1.0f});
    }();
};

/// A 300 x 200 picture whose pixel (x, y) shows the centre of spot paint(x, y) (-1: background;
/// 2: the sphere outside both spots).
core::ImageLayers paint(const SpotsOnASphere& scene, const std::function<int(int, int)>& spotAt)
{
    core::ImageLayers layers(300, 200);
    core::Channel& region = layers.add("region");
    core::Channel &x = layers.add("P.X"), &y = layers.add("P.Y"), &z = layers.add("P.Z");
    core::Channel& scalar = layers.add("scalar");
    for (int row = 0; row < 200; ++row)
        for (int column = 0; column < 300; ++column) {
            const std::size_t i = std::size_t(row) * 300 + std::size_t(column);
            const int spot = spotAt(column, row);
            if (spot < 0) continue;
            region[i] = float(spot == 1 ? render::Region::Indirect : render::Region::Direct);
            const glm::vec3 p = spot < 2 ? scene.spots.centres[std::size_t(spot)] : glm::vec3(0.0f, 0.0f, 1.0f);
            x[i] = p.x, y[i] = p.y, z[i] = p.z;
            scalar[i] = spot < 2 ? 1.0f : 0.0f;
        }
    return layers;
}

TEST(HotSpotShape, RectanglesDiscsSplitsAndZigzagsAgainstTheirExactFigures)
{
    const SpotsOnASphere scene;
    ASSERT_EQ(scene.reveal.regionCount(), 2u);
    const int first = scene.reveal.regionAt(scene.spots.centres[0]), second = scene.reveal.regionAt(scene.spots.centres[1]);
    ASSERT_GE(first, 0);
    ASSERT_EQ(first + second, 1) << "each spot's centre lies in its own region";

    // Spot 0 a 40 x 25 rectangle, spot 1 a disc of radius 60; the rest of the sphere around them.
    const auto shapes = hotSpotShapes(scene.reveal, paint(scene, [](int x, int y) {
        if (x >= 10 && x < 50 && y >= 20 && y < 45) return 0;
        if (std::hypot(x + 0.5 - 180.0, y + 0.5 - 100.0) < 60.0) return 1;
        return x < 280 ? 2 : -1;
    }));
    ASSERT_EQ(shapes.size(), 2u);
    const HotSpotShape& rectangle = shapes[std::size_t(first)];
    const HotSpotShape& disc = shapes[std::size_t(second)];
    EXPECT_EQ(rectangle.pixels, 1000u);
    EXPECT_DOUBLE_EQ(rectangle.largestShare, 1.0);
    EXPECT_DOUBLE_EQ(rectangle.outlineRatio, 1.0);
    EXPECT_NEAR(double(disc.pixels), M_PI * 3600.0, 60.0);
    EXPECT_DOUBLE_EQ(disc.largestShare, 1.0);
    EXPECT_NEAR(disc.outlineRatio, 4.0 / M_PI, 0.02);

    // Spot 0 split into 900 and 100 pixels; spot 1 a zigzag band 4 pixels wide, its teeth 20 high:
    // about 6 pixel edges of outline a column against a hull about 2 (160 + 24) round.
    const auto split = hotSpotShapes(scene.reveal, paint(scene, [](int x, int y) {
        if (x >= 10 && x < 40 && y >= 10 && y < 40) return 0;
        if (x >= 60 && x < 70 && y >= 10 && y < 20) return 0;
        const int tooth = 10, phase = x % (2 * tooth), height = 40 + 2 * (phase < tooth ? phase : 2 * tooth - phase);
        if (x >= 100 && x < 260 && y >= height && y < height + 4) return 1;
        return -1;
    }));
    EXPECT_EQ(split[std::size_t(first)].pixels, 1000u);
    EXPECT_DOUBLE_EQ(split[std::size_t(first)].largestShare, 0.9);
    EXPECT_DOUBLE_EQ(split[std::size_t(second)].largestShare, 1.0);
    EXPECT_GT(split[std::size_t(second)].outlineRatio, 2.0);

    // Nothing shows a spot: no pixels, no shape.
    const auto none = hotSpotShapes(scene.reveal, paint(scene, [](int, int) { return 2; }));
    EXPECT_EQ(none[0].pixels, 0u);
    EXPECT_EQ(none[0].largestShare, 0.0);
}

}  // namespace
}  // namespace ivis::optimize
