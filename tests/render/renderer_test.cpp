// The TBB renderer: results independent of the thread count, statistics consistent with the layers,
// the regions each method produces, and regression images of the vessel tree.
//
// Regression images: tests/regression/<method>.png (see tests/regression/README.md). After an
// intended change of the pictures, LOOK at the new ones and regenerate them with
//   IVIS_REGENERATE_REGRESSION=1 build/tests/ivis_tests --gtest_filter='Regression*'
// (run from the source tree root; the files are written into the source tree via IVIS_SOURCE_DIR).
#include "render/scene_fixture.h"
#include "test_support.h"

#include <ivis/core/colormap.h>
#include <ivis/core/image_io.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>
#include <ivis/render/screen_map.h>
#include <ivis/render/shadow.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace ivis::render {
namespace {


/// Options used by these tests: small image, the data's range, each method's defaults (the
/// mirror's is curved: a flat one shows little of the back).
RenderOptions testOptions(const core::SurfaceField& field, const std::string& method, int size, int spp)
{
    RenderOptions options;
    options.width = options.height = size;
    options.samplesPerPixel = spp;
    options.method = makeMethod(method);
    options.shading.scale.range = core::scalarRangeFromData(field.values);
    options.scalarName = field.name;
    return options;
}

RenderResult renderWithThreads(int threads, const RenderScene& scene, const core::Camera& camera,
                               const RenderOptions& options)
{
    tbb::task_arena arena(threads);
    RenderResult result;
    arena.execute([&] { result = renderImage(scene, camera, options); });
    return result;
}

/// Bitwise equality of two float arrays (NaN payloads included).
bool sameBits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

TEST(Renderer, SameResultWithOneAndTwoThreads)
{
    const auto& fixture = test::vesselScene();
    const core::Camera camera = core::Camera::fromAngles(75, 30);
    for (const std::string& method : methodNames())
        for (int spp : {1, 4}) {
            const std::string name = method + " spp " + std::to_string(spp);
            const RenderOptions options = testOptions(fixture.field, method, 64, spp);
            const RenderResult one = renderWithThreads(1, *fixture.scene, camera, options);
            const RenderResult two = renderWithThreads(2, *fixture.scene, camera, options);
            ASSERT_EQ(one.image.pixels().size(), two.image.pixels().size());
            EXPECT_TRUE(sameBits(one.image.pixels().data(), two.image.pixels().data(),
                                 one.image.pixels().size() * sizeof(glm::vec4)))
                << name << ": image differs";
            ASSERT_EQ(one.layers.channels().size(), two.layers.channels().size());
            for (const auto& [layer, values] : one.layers.channels()) {
                const core::Channel& other = two.layers.channel(layer);
                ASSERT_EQ(values.size(), other.size());
                EXPECT_TRUE(sameBits(values.data(), other.data(), values.size() * sizeof(float)))
                    << name << ": layer " << layer << " differs";
            }
            EXPECT_EQ(one.stats.pixelsDirect, two.stats.pixelsDirect) << name;
            EXPECT_EQ(one.stats.pixelsIndirect, two.stats.pixelsIndirect) << name;
            EXPECT_EQ(one.stats.pixelsBackground, two.stats.pixelsBackground) << name;
            EXPECT_EQ(one.stats.raysLaunched, two.stats.raysLaunched) << name;
            EXPECT_EQ(one.stats.raysLanded, two.stats.raysLanded) << name;
            EXPECT_EQ(one.stats.totalSteps, two.stats.totalSteps) << name;
            EXPECT_EQ(one.stats.nanPixels, two.stats.nanPixels) << name;
        }
}

TEST(Renderer, StatsMatchTheRegionLayer)
{
    const auto& fixture = test::vesselScene();
    const core::Camera camera = core::Camera::fromAngles(90, 0);
    for (const std::string& method : methodNames())
        for (int spp : {1, 3}) {
            const std::string name = method + " spp " + std::to_string(spp);
            const RenderOptions options = testOptions(fixture.field, method, 48, spp);
            const RenderResult result = renderImage(*fixture.scene, camera, options);
            const core::Channel& region = result.layers.channel("region");
            const core::Channel& triangle = result.layers.channel("triangle");
            const core::Channel& px = result.layers.channel("P.X");
            const core::Channel& depth = result.layers.channel("depth");
            std::size_t counts[3] = {0, 0, 0};
            for (std::size_t i = 0; i < region.size(); ++i) {
                ASSERT_TRUE(region[i] == 0.0f || region[i] == 1.0f || region[i] == 2.0f) << region[i];
                ++counts[std::size_t(region[i])];
                const bool shown = region[i] != float(Region::Background);
                EXPECT_EQ(triangle[i] >= 0.0f, shown) << name << " pixel " << i;
                EXPECT_EQ(std::isnan(px[i]), !shown) << name << " pixel " << i;
                if (shown) { EXPECT_GT(depth[i], 0.0f) << name << " pixel " << i; }
            }
            EXPECT_EQ(result.stats.pixelsBackground, counts[0]) << name;
            EXPECT_EQ(result.stats.pixelsDirect, counts[1]) << name;
            EXPECT_EQ(result.stats.pixelsIndirect, counts[2]) << name;
            EXPECT_EQ(counts[0] + counts[1] + counts[2], std::size_t(48 * 48));
            EXPECT_LE(result.stats.raysLanded, result.stats.raysLaunched) << name;
            EXPECT_LE(result.stats.raysLaunched, std::size_t(48 * 48 * spp)) << name;
            EXPECT_GT(result.stats.pixelsDirect, 0u) << name;
            if (method == "front" || method == "backfaces") {
                EXPECT_EQ(result.stats.raysLaunched, 0u) << name;
                EXPECT_EQ(result.stats.totalSteps, 0u) << name;
            } else {
                // Every indirect pixel centre is a landed ray.
                EXPECT_GE(result.stats.raysLanded, result.stats.pixelsIndirect) << name;
                if (spp == 1) { EXPECT_EQ(result.stats.raysLanded, result.stats.pixelsIndirect) << name; }
                EXPECT_GT(result.stats.pixelsIndirect, 0u) << name;
            }
            EXPECT_EQ(result.stats.nanPixels, 0u) << name;
        }
}

TEST(Renderer, FrontHasNoIndirectPixels)
{
    for (const test::SceneFixture* fixture : {&test::sphereScene(), &test::vesselScene()})
        for (const core::Camera& camera : {core::Camera::fromAngles(90, 0), core::Camera::fromAngles(30, 250)}) {
            const RenderResult result =
                renderImage(*fixture->scene, camera, testOptions(fixture->field, "front", 48, 1));
            EXPECT_EQ(result.stats.pixelsIndirect, 0u);
            EXPECT_GT(result.stats.pixelsDirect, 0u);
            for (float r : result.layers.channel("region")) EXPECT_NE(r, float(Region::Indirect));
        }
}

TEST(Renderer, InverseVisRingSurroundsTheSphere)
{
    const auto& fixture = test::sphereScene();
    const int size = 96;
    const RenderResult result =
        renderImage(*fixture.scene, core::Camera(), testOptions(fixture.field, "inversevis", size, 1));
    const core::Channel& region = result.layers.channel("region");
    double maxDirect = 0.0, minIndirect = 1e30, maxIndirect = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double r = std::hypot(x + 0.5 - 0.5 * size, y + 0.5 - 0.5 * size);
            const float g = region[std::size_t(y) * size + x];
            if (g == float(Region::Direct)) maxDirect = std::max(maxDirect, r);
            if (g == float(Region::Indirect)) {
                minIndirect = std::min(minIndirect, r);
                maxIndirect = std::max(maxIndirect, r);
            }
        }
    ASSERT_GT(result.stats.pixelsIndirect, 100u);
    EXPECT_GE(minIndirect, maxDirect - 2.0) << "indirect pixels inside the direct disc";
    // Analytic radii (pixels) of the sphere's and the hull's silhouettes seen from 2.5.
    const double tanHalf = std::tan(0.5 * core::kDefaultFovYDeg * M_PI / 180.0);
    const double sphere = std::tan(std::asin(1.0 / 2.5)) / tanHalf * 0.5 * size;
    const double hull = std::tan(std::asin(1.4 / 2.5)) / tanHalf * 0.5 * size;
    EXPECT_NEAR(maxDirect, sphere, 1.5);
    EXPECT_LE(maxIndirect, hull + 1.5);
    EXPECT_GE(maxIndirect, hull - 3.0);
    // The ring is closed: pixels on every side of the disc are indirect.
    for (int k = 0; k < 16; ++k) {
        const double angle = 2.0 * M_PI * (k + 0.5) / 16.0, r = 0.5 * (sphere + hull);
        const int x = int(0.5 * size + r * std::cos(angle)), y = int(0.5 * size + r * std::sin(angle));
        EXPECT_EQ(region[std::size_t(y) * size + x], float(Region::Indirect)) << "angle " << angle;
    }
}

TEST(Renderer, UnshadedIndirectPixelsAreTheColourBarsColour)
{
    // --unshaded-indirect is for reading the back side's values against the bar: each indirect
    // pixel is exactly the bar's colour of the scalar it shows (it was dimmed to 0.75 of it), while
    // the shaded picture's are dimmed and lit.
    const auto& fixture = test::sphereScene();
    RenderOptions options = testOptions(fixture.field, "inversevis", 64, 1);
    options.shading.shadeIndirect = false;
    const RenderResult flat = renderImage(*fixture.scene, core::Camera(), options);
    options.shading.shadeIndirect = true;
    const RenderResult lit = renderImage(*fixture.scene, core::Camera(), options);
    const core::Colormap& colours = core::colormap(options.shading.colormap);
    const core::Channel& region = flat.layers.channel("region");
    const core::Channel& scalar = flat.layers.channel("scalar");
    std::size_t checked = 0, darker = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const std::size_t i = std::size_t(y) * 64 + x;
            if (region[i] != float(Region::Indirect) || std::isnan(scalar[i])) continue;
            const glm::vec3 bar = colours.at(options.shading.scale.position(scalar[i]));
            const glm::vec4 pixel = flat.image.at(x, y);
            EXPECT_LE(glm::length(glm::vec3(pixel) - bar), 1e-5f) << x << "," << y;
            darker += glm::length(glm::vec3(lit.image.at(x, y))) < 0.76f * glm::length(bar) + 1e-6f;
            ++checked;
        }
    EXPECT_GT(checked, 300u);
    EXPECT_EQ(darker, checked);
}

// On an open mesh (unsigned distance) the trilinear phi near a wall stays around 0.5..1 voxel at
// the samples, so a shadow ray could step across a thin wall; shadowFactor detects the crossing.
TEST(Renderer, ShadowRaysDoNotLeakThroughOpenWalls)
{
    const auto& fixture = test::vesselScene();
    const RenderScene& scene = *fixture.scene;
    const core::CameraFrame frame(core::Camera::fromAngles(90, 0), 128, 128);
    const ScreenMap screen(scene, frame, makeMethod("backfaces"));
    const Shader shader(scene, frame, ShadingOptions{}, *makeMethod("backfaces"));
    auto sampler = scene.distance().sampler();
    const float voxel = scene.distance().voxelSize();
    const core::Bounds3 surfaceBox = hullBounds(scene.bounds(), 0.0f, voxel);
    int blocked = 0, leaks = 0;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const PixelMapping m = screen.map(x + 0.5, y + 0.5, sampler);
            if (m.region != Region::Direct) continue;
            glm::vec3 n = shadingNormal(scene.mesh(), scene.normals(), m.point);
            if (glm::dot(n, m.arrival) > 0.0f) n = -n;  // the side seen, as the shader does
            if (glm::dot(n, shader.toLight()) <= 0.0f) continue;
            // The exact segment toward the light (from the shadow ray's start) meets the mesh.
            if (!scene.bvh().intersect(m.point.position + 2.0f * voxel * n, shader.toLight(), 0.0f, 6.0f).hit())
                continue;
            ++blocked;
            leaks += shadowFactor(sampler, m.point.position, n, shader.toLight(), surfaceBox) > 0.0f;
        }
    ASSERT_GT(blocked, 500);
    EXPECT_LE(leaks, blocked / 500) << leaks << " of " << blocked << " blocked shadow rays report light";
}

// A shadow ray leaving a convex object meets nothing: it must come back fully lit, also where it
// runs beyond the field's reach (phi clamped at 0.6 there; min(8 phi / t) over t < 6 would give 0.8).
TEST(Renderer, ShadowRaysLeavingAConvexObjectAreFullyLit)
{
    const RenderScene& scene = *test::sphereScene().scene;
    auto sampler = scene.distance().sampler();
    const core::Bounds3 surfaceBox = hullBounds(scene.bounds(), 0.0f, scene.distance().voxelSize());
    std::mt19937 random(7);
    std::normal_distribution<float> gauss;
    float darkest = 1.0f;
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 normal = glm::normalize(glm::vec3(gauss(random), gauss(random), gauss(random)));
        glm::vec3 tangent = glm::cross(normal, glm::normalize(glm::vec3(gauss(random), gauss(random), gauss(random))));
        tangent = glm::normalize(tangent);
        const float tilt = 0.6f;  // radians between the normal and the light
        const glm::vec3 toLight = std::cos(tilt) * normal + std::sin(tilt) * tangent;
        darkest = std::min(darkest, shadowFactor(sampler, normal, normal, toLight, surfaceBox));
    }
    EXPECT_GE(darkest, 0.999f);
}

// ---------------------------------------------------------------------------------------------
// Regression images.

std::string regressionPath(const std::string& method)
{
    return std::string(IVIS_SOURCE_DIR) + "/tests/regression/" + method + ".png";
}

/// Fixed options of the regression pictures (curved mirror w = (0.3, 0.3, 0, 0, 0)).
RenderOptions regressionOptions(const std::string& method)
{
    const auto& field = test::vesselScene().field;
    RenderOptions options = testOptions(field, method, 256, 1);
    options.legend = true;
    options.outline = true;
    options.shading.shadows = true;
    return options;
}

/// Renders the vessel tree with @a method and compares it with its stored PNG (sRGB bytes): mean
/// absolute difference below 2/255 and at most 1% of pixels off by more than 16/255.
void checkRegression(const std::string& method)
{
    const auto& fixture = test::vesselScene();
    const RenderResult result = renderImage(*fixture.scene, core::Camera::fromAngles(90, 0), regressionOptions(method));
    const std::string path = regressionPath(method);
    const char* regenerate = std::getenv("IVIS_REGENERATE_REGRESSION");
    if (regenerate && std::string(regenerate) == "1") {
        std::filesystem::create_directories(std::filesystem::path(path).parent_path());
        core::writePng(result.figure, path, false);
        std::printf("wrote %s\n", path.c_str());
        return;
    }
    if (!std::filesystem::exists(path))
        FAIL() << "missing regression image " << path
               << "; render and inspect it with: IVIS_REGENERATE_REGRESSION=1 build/tests/ivis_tests "
                  "--gtest_filter='Regression*' (from the source tree root)";
    // Encode the new picture exactly as the stored one was (8-bit sRGB PNG), then compare bytes.
    test::TempDir dir;
    core::writePng(result.figure, dir.file("new.png"), false);
    const core::Image now = core::readPng(dir.file("new.png"));
    const core::Image reference = core::readPng(path);
    ASSERT_EQ(reference.width(), now.width()) << path;
    ASSERT_EQ(reference.height(), now.height()) << path;
    double sum = 0.0;
    std::size_t far = 0;
    for (std::size_t i = 0; i < now.pixels().size(); ++i) {
        float worst = 0.0f;
        for (int c = 0; c < 3; ++c) {
            const float d = std::abs(core::srgbFromLinear(now.pixels()[i][c]) -
                                     core::srgbFromLinear(reference.pixels()[i][c]));
            sum += d;
            worst = std::max(worst, d);
        }
        if (worst > 16.0f / 255.0f) ++far;
    }
    const double mean = sum / (3.0 * double(now.pixels().size()));
    const double farFraction = double(far) / double(now.pixels().size());
    EXPECT_LT(mean, 2.0 / 255.0) << path << ": mean absolute difference " << mean * 255.0 << "/255";
    EXPECT_LE(farFraction, 0.01) << path << ": " << far << " pixels differ by more than 16/255";
}

TEST(RegressionImage, EveryMethodMatchesItsStoredPicture)
{
    for (const std::string& method : methodNames()) {
        SCOPED_TRACE(method);
        checkRegression(method);
    }
}

}  // namespace
}  // namespace ivis::render
