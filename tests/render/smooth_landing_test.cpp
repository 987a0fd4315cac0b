// Curved rays on the sampled distance field against the same rays on the exact distance of the unit
// sphere (issue 12's acceptance): the landing point must be an accurate, smooth function of the pixel.
#include "test_support.h"

#include <ivis/core/surface_source.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/pixel_mapping.h>
#include <ivis/render/screen_map.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <mutex>
#include <vector>

namespace ivis::render {
namespace {

/// The exact distance of the unit sphere, with the FieldSampler interface of integrateCurvedRay.
struct UnitSphereSampler {
    float phiAndGradient(const glm::vec3& p, glm::vec3& gradient)
    {
        const float length = glm::length(p);
        gradient = p / length;
        return length - 1.0f;
    }
};

/// Distance (in fine voxels) between each indirect pixel's landed point and the exact landing
/// point of the same ray, projected onto the sphere; a ray that lands on only one field counts as
/// infinitely far.
std::vector<float> landingErrors(const RenderScene& scene, float alpha, int pixels)
{
    const MethodPtr method = makeMethod("inversevis", {{"alpha", {alpha}}});
    const core::Camera camera = frameView(scene, core::Camera::fromAngles(90.0, 0.0), *method, 1.0);
    const core::CameraFrame frame(camera, pixels, pixels);
    const ScreenMap screen(scene, frame, method);
    const CurvedRayMap& rays = *screen.curvedRays();
    const CurvedRayParams& params = method->curved()->rayParams();
    const float epsilon = landingEpsilon(params, scene.distance());
    const float escape = escapeDistance(scene.distance());
    const float voxel = scene.distance().voxelSize();

    std::vector<float> errors;
    std::mutex mutex;
    tbb::parallel_for(0, pixels, [&](int y) {
        auto sampler = scene.distance().sampler();
        UnitSphereSampler exact;
        std::vector<float> row;
        for (int x = 0; x < pixels; ++x) {
            CurvedRayStart start;
            if (!rays.start(x + 0.5, y + 0.5, sampler, start)) continue;
            const PixelMapping landed = rays.landing(start, sampler);
            if (landed.region != Region::Indirect) continue;
            const CurvedRayEnd end =
                integrateCurvedRay(exact, start.seed, rays.method().launchVelocity(start, 0), params, epsilon, escape);
            row.push_back(end.landed ? glm::length(landed.point.position - glm::normalize(end.position)) / voxel
                                     : std::numeric_limits<float>::infinity());
        }
        const std::lock_guard<std::mutex> lock(mutex);
        errors.insert(errors.end(), row.begin(), row.end());
    });
    std::sort(errors.begin(), errors.end());
    return errors;
}

TEST(SmoothLanding, CurvedRaysLandWhereTheExactSphereFieldLandsThem)
{
    const core::SurfaceField field = core::loadSurface(test::sharedMesh("sphere_ico5.ply"));
    vdb::VolumeOptions options;
    options.resolution = 200;
    const vdb::SurfaceVolume volume = vdb::buildSurfaceVolume(field.mesh, options);
    const RenderScene scene(field, volume);
    for (const float alpha : {0.1f, 0.5f, 1.5f}) {
        const std::vector<float> errors = landingErrors(scene, alpha, 1000);
        ASSERT_GT(errors.size(), 100000u) << "alpha " << alpha;
        const float p99 = errors[std::size_t(0.99 * double(errors.size() - 1))];
        const float worst = errors.back();
        std::printf("alpha %.1f: %zu indirect pixels, landing error p50 %.4f p99 %.4f max %.4f voxel\n", alpha,
                    errors.size(), errors[errors.size() / 2], p99, worst);
        EXPECT_LE(p99, 0.1f) << "alpha " << alpha;
        EXPECT_LE(worst, 1.0f) << "alpha " << alpha;
    }
}

}  // namespace
}  // namespace ivis::render
