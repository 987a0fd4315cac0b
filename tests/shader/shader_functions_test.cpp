// The functions written both in C++ (render/, core/) and in the viewer's GLSL (assets/shaders/),
// each run on the same inputs on both sides: the CPU function against the shader's, run on the
// GPU by a compute pass (shader_harness.h). docs/viewer.md, "Functions on both sides", lists them.
// Both sides compute in float; the bounds allow the GPU's own rounding (fused multiply-adds, its
// pow and division) and fail for any change of a formula or a constant on one side.
#include "shader_harness.h"

#include "render/scene_fixture.h"

#include <dense_slices.h>
#include <gpu_frame.h>
#include <gpu_uniforms.h>
#include <uniform_set.h>
#include <volume_textures.h>

#include <ivis/core/image.h>
#include <ivis/core/ray_box.h>
#include <ivis/render/curved_ray.h>
#include <ivis/render/dense_grid.h>
#include <ivis/render/inversevis_wrap_method.h>
#include <ivis/render/method_registry.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace ivis::test {
namespace {

glm::vec3 randomVector(std::mt19937& random, float lo, float hi)
{
    std::uniform_real_distribution<float> u(lo, hi);
    return {u(random), u(random), u(random)};
}

glm::vec3 xyz(const glm::vec4& v) { return {v.x, v.y, v.z}; }

// render::detail::blend, the distance field's interpolation of 8 (phi, gradient) corners, against
// distance_field.glsl's blend.
TEST(ShaderFunctions, BlendIsTheCpusBlend)
{
    std::mt19937 random(1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float voxel = 0.01f;
    std::vector<glm::vec4> inputs;
    std::vector<glm::vec4> expected;
    for (int item = 0; item < 2000; ++item) {
        glm::vec4 corners[8];
        for (glm::vec4& c : corners) {
            const glm::vec3 g = glm::normalize(randomVector(random, -1.0f, 1.0f));
            c = glm::vec4(0.05f * (unit(random) - 0.3f), g);
            inputs.push_back(c);
        }
        const glm::vec3 t(unit(random), unit(random), unit(random));
        inputs.emplace_back(t, voxel);
        expected.push_back(render::detail::blend(corners, t, voxel));
    }
    ShaderCall call;
    call.inputsPerItem = 9;
    call.body = "vec4 c[8];\n"
                "for (int i = 0; i < 8; ++i) c[i] = IN(i);\n"
                "OUT(0) = blend(c, IN(8).xyz, IN(8).w);";
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(gpu[i].x, expected[i].x, 1e-7f) << "phi of item " << i;
        EXPECT_LT(glm::length(xyz(gpu[i]) - xyz(expected[i])), 1e-6f) << "gradient of item " << i;
    }
}

// render::initialVelocity (alpha g x (r x g), r where the gradient vanishes) against curved_ray.glsl's.
TEST(ShaderFunctions, InitialVelocityIsTheCpus)
{
    std::mt19937 random(2);
    std::uniform_real_distribution<float> alpha(0.0f, 4.0f);
    std::vector<glm::vec4> inputs;
    std::vector<glm::vec3> expected;
    for (int item = 0; item < 2000; ++item) {
        const glm::vec3 gradient = item % 100 == 0 ? glm::vec3(0.0f) : randomVector(random, -1.0f, 1.0f);
        const glm::vec3 view = glm::normalize(randomVector(random, -1.0f, 1.0f));
        const float a = alpha(random);
        inputs.emplace_back(gradient, a);
        inputs.emplace_back(view, 0.0f);
        expected.push_back(render::initialVelocity(gradient, view, a));
    }
    ShaderCall call;
    call.inputsPerItem = 2;
    call.body = "OUT(0) = vec4(initialVelocity(IN(0).xyz, IN(1).xyz, IN(0).w), 0.0);";
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_LT(glm::length(xyz(gpu[i]) - expected[i]), 2e-6f * std::max(1.0f, glm::length(expected[i]))) << i;
}

// The wrap's launch across its ring (WrapLaunch::alphaAt and directionAt) against
// method_inversevis-wrap.glsl's wrapLaunch, at the method's parameters as the viewer sets them.
TEST(ShaderFunctions, WrapLaunchIsTheCpus)
{
    const render::MethodPtr method =
        render::makeMethod("inversevis-wrap", {{"wrap_speed", {2.2f}}, {"wrap_tilt", {0.7f}}});
    const render::WrapLaunch& launch = dynamic_cast<const render::InverseVisWrapMethod&>(*method).launch();
    std::mt19937 random(3);
    std::uniform_real_distribution<float> ring(0.0f, 1.0f);
    std::vector<glm::vec4> inputs;
    std::vector<glm::vec3> expected;
    for (int item = 0; item < 2000; ++item) {
        const glm::vec3 outward = glm::normalize(randomVector(random, -1.0f, 1.0f));
        glm::vec3 along = randomVector(random, -1.0f, 1.0f);
        along = glm::normalize(along - glm::dot(along, outward) * outward);
        const float t = ring(random);
        inputs.emplace_back(along, t);
        inputs.emplace_back(outward, 0.0f);
        expected.push_back(launch.alphaAt(t) * launch.directionAt(along, outward, t));
    }
    ShaderCall call;
    call.inputsPerItem = 2;
    call.body = "OUT(0) = vec4(wrapLaunch(IN(0).w, IN(0).xyz, IN(1).xyz), 0.0);";
    call.setUniforms = [&](app::GlProgram& program) {
        for (const auto& [key, values] : method->values())
            if (values.size() == 1) program.set(app::parameterUniform(key).c_str(), values[0]);
    };
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_LT(glm::length(xyz(gpu[i]) - expected[i]), 2e-6f) << i;
}

// core::rayBoxInterval against hull_search.glsl's boxInterval (the hull's box).
TEST(ShaderFunctions, BoxIntervalIsTheCpus)
{
    const core::Bounds3 box{{-0.8, -0.6, -0.9}, {0.7, 0.9, 0.5}};
    std::mt19937 random(4);
    std::vector<glm::vec4> inputs;
    std::vector<glm::vec4> expected;
    for (int item = 0; item < 2000; ++item) {
        // Rays from outside toward points round the box: most meet it, some pass by.
        const glm::vec3 origin = randomVector(random, -3.0f, 3.0f);
        glm::vec3 direction = glm::normalize(randomVector(random, -1.2f, 1.2f) - origin);
        if (item % 50 == 0) direction = glm::vec3(0.0f, 0.0f, 1.0f);  // axis-parallel: two slabs never crossed
        inputs.emplace_back(origin, 0.0f);
        inputs.emplace_back(direction, 0.0f);
        float tEnter = 0.0f, tExit = 0.0f;
        const bool hit = core::rayBoxInterval(origin, direction, box, tEnter, tExit);
        expected.emplace_back(hit ? 1.0f : 0.0f, tEnter, tExit, 0.0f);
    }
    ShaderCall call;
    call.inputsPerItem = 2;
    call.body = "float tEnter, tExit;\n"
                "bool hit = boxInterval(IN(0).xyz, IN(1).xyz, tEnter, tExit);\n"
                "OUT(0) = vec4(hit ? 1.0 : 0.0, tEnter, tExit, 0.0);";
    call.setUniforms = [&](app::GlProgram& program) {
        program.set("uHullLo", glm::vec3(box.lo));
        program.set("uHullHi", glm::vec3(box.hi));
    };
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    int hits = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_EQ(gpu[i].x, expected[i].x) << "whether ray " << i << " meets the box";
        if (expected[i].x == 0.0f) continue;
        ++hits;
        EXPECT_NEAR(gpu[i].y, expected[i].y, 1e-5f) << i;
        EXPECT_NEAR(gpu[i].z, expected[i].z, 1e-5f) << i;
    }
    EXPECT_GT(hits, 1000);
}

// core::srgbFromLinear and linearFromSrgb (the PNGs' encoding) against srgb.glsl's.
TEST(ShaderFunctions, SrgbEncodingIsTheCpus)
{
    std::vector<glm::vec4> inputs;
    for (int i = 0; i <= 3000; ++i) {
        const float v = float(i) / 3000.0f;
        inputs.emplace_back(v, v * v, std::sqrt(v), 0.0f);
    }
    ShaderCall call;
    call.outputsPerItem = 2;
    call.body = "OUT(0) = vec4(srgbFromLinear(IN(0).xyz), 0.0);\n"
                "OUT(1) = vec4(linearFromSrgb(IN(0).xyz), 0.0);";
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(gpu[2 * i][c], core::srgbFromLinear(inputs[i][c]), 2e-6f) << inputs[i][c];
            EXPECT_NEAR(gpu[2 * i + 1][c], core::linearFromSrgb(inputs[i][c]), 2e-6f) << inputs[i][c];
        }
}

// render::findClosestApproach, the wrap's seed (the centre of the view ray's valley of phi), against
// method_inversevis-wrap.glsl's closestApproach, on the generated vessel tree's distance field
// uploaded as the viewer uploads it (at the volume's own resolution: the same voxels).
TEST(ShaderFunctions, ClosestApproachIsTheCpus)
{
    const SceneFixture& fixture = vesselScene();
    const render::RenderScene& scene = *fixture.scene;
    const app::DenseSlices slices = app::buildDenseSlices(scene, app::DenseSliceOptions{}, nullptr);
    ASSERT_TRUE(slices.exact()) << "the shaders must sample the CPU's own voxels";
    app::VolumeTextures textures;
    textures.upload(slices);
    textures.bind();
    const float voxel = float(fixture.volume.voxelSize());
    app::UniformSet volumeUniforms;
    app::keepVolumeUniforms(volumeUniforms, slices, 0.0f, render::hullBounds(scene.bounds(), 0.0f, voxel));

    app::GpuFrame frame;
    frame.camera = core::Camera::fromAngles(70.0, 30.0);
    frame.width = frame.height = 96;
    frame.method = render::makeMethod("inversevis-wrap");
    const core::CameraFrame camera(frame.camera, frame.width, frame.height);
    const float hullOffset = frame.method->curved()->rayParams().hullOffset;
    const core::Bounds3 hullBox = render::hullBounds(scene.bounds(), hullOffset, voxel);

    std::vector<glm::vec4> inputs;
    std::vector<glm::vec4> expected;
    render::DistanceField::Sampler sampler = scene.distance().sampler();
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const core::CameraRay ray = camera.ray(x + 0.5, y + 0.5);
            const glm::vec3 origin(ray.origin), direction(ray.direction);
            inputs.emplace_back(origin, 0.0f);
            inputs.emplace_back(direction, 0.0f);
            glm::vec3 seed(0.0f);
            float distance = 0.0f;
            const bool found =
                render::findClosestApproach(sampler, origin, direction, hullOffset, hullBox, seed, distance, nullptr);
            expected.emplace_back(seed, found ? distance : -1.0f);
        }
    ShaderCall call;
    call.inputsPerItem = 2;
    call.body = "vec3 seed;\n"
                "float distance;\n"
                "bool found = closestApproach(IN(0).xyz, IN(1).xyz, seed, distance);\n"
                "OUT(0) = vec4(seed, found ? distance : -1.0);";
    call.setUniforms = [&](app::GlProgram& program) {
        volumeUniforms.applyTo(program);
        app::setIndirectUniforms(program, frame, camera, scene.field(), scene.bounds(), {voxel, slices.reach});
    };
    const std::vector<glm::vec4> gpu = runShaderCall(call, inputs);
    // A ray whose valley bottom lies within a float's rounding of the hull may be found on one side
    // only; every other seed, and phi there, must agree to a thousandth of a voxel (measured: 4e-4).
    int found = 0, disagreeing = 0;
    double largest = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const bool cpuFound = expected[i].w >= 0.0f, gpuFound = gpu[i].w >= 0.0f;
        if (cpuFound != gpuFound) {
            ++disagreeing;
            EXPECT_NEAR(std::max(expected[i].w, gpu[i].w), hullOffset, 1e-4f) << "pixel " << i;
            continue;
        }
        if (!cpuFound) continue;
        ++found;
        largest = std::max(largest, double(glm::length(xyz(gpu[i]) - xyz(expected[i]))) / voxel);
        EXPECT_NEAR(gpu[i].w, expected[i].w, 1e-3f * voxel) << "phi at the seed of pixel " << i;
    }
    EXPECT_GT(found, 2000);
    EXPECT_LE(disagreeing, 2);
    EXPECT_LT(largest, 1e-3) << "largest seed difference in voxels";
    std::cout << found << " seeds, largest difference " << largest << " voxel\n";
}

}  // namespace
}  // namespace ivis::test
