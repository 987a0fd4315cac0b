// The even-sampling bound of the surface visibility: a flat square is seen whole by enough points
// and by no more area than that of as many voxels as points; on the unit icosphere an even spread
// of half a million points sees at least 99.9% of the area (docs/measures.md) but fewer voxels.
#include <ivis/optimize/sampling_bound.h>

#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/triangle_bvh.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivis::optimize {
namespace {

/// The square [0.001, 0.399]^2 at z = 0.0125 (a voxel layer's middle at resolution 200): 16 x 16
/// voxels, each holding at least 92% of a voxel face of it.
core::TriangleMesh voxelAlignedSquare()
{
    core::TriangleMesh mesh;
    const float lo = 0.001f, hi = 0.399f, z = 0.0125f;
    mesh.positions = {{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.dataTriangleCount = 2;
    return mesh;
}

TEST(SamplingBound, AFlatSquareIsSeenWholeByEnoughPointsAndByNoMoreVoxelsThanPoints)
{
    const core::TriangleMesh square = voxelAlignedSquare();
    const SurfaceVoxels voxels(square, 200);
    ASSERT_EQ(voxels.count(), 256u);
    EXPECT_DOUBLE_EQ(evenSamplingBound(square, voxels, 256 * 16), 1.0);
    const double fullVoxel = 0.025 * 0.025 / voxels.totalArea();  // a voxel face's share of the square
    for (std::size_t samples : {1, 10, 64, 200})
        EXPECT_LE(evenSamplingBound(square, voxels, samples), double(samples) * fullVoxel) << samples;
    EXPECT_GT(evenSamplingBound(square, voxels, 64), 0.15);  // spread, not clumped in a corner
    EXPECT_THROW(evenSamplingBound(square, voxels, 0), ValueError);
}

/// The surface voxels of the icosphere that @a count points of a Fibonacci spread over the unit
/// sphere (an even spread independent of the triangles), cast onto the icosphere from its centre, fall in.
std::vector<std::uint64_t> fibonacciKeys(const core::TriangleMesh& sphere, const SurfaceVoxels& voxels, std::size_t count)
{
    const core::TriangleBvh bvh(sphere);
    const double goldenAngle = M_PI * (3.0 - std::sqrt(5.0));
    std::vector<std::uint64_t> keys;
    for (std::size_t i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * double(i) + 1.0) / double(count), r = std::sqrt(1.0 - z * z);
        const glm::vec3 d(float(r * std::cos(goldenAngle * double(i))), float(r * std::sin(goldenAngle * double(i))), float(z));
        const core::RayHit hit = bvh.intersect(glm::vec3(0.0f), d);
        if (hit.hit()) keys.push_back(voxels.keyOf(hit.t * d));
    }
    return keys;
}

TEST(SamplingBound, HalfAMillionEvenPointsSeeTheIcospheresWholeAreaButNotAllItsVoxels)
{
    // A voxel the sphere only grazes holds a sliver of it: by voxel count a million even points
    // see about 98% of the surface voxels, by area 99.96% (docs/measures.md: 500,000 see 99.9%).
    const core::SurfaceField sphere = core::makeSphere(5);
    const SurfaceVoxels voxels(sphere.mesh, 200);
    EXPECT_NEAR(voxels.totalArea(), 4.0 * M_PI, 0.01 * 4.0 * M_PI);
    std::vector<std::uint64_t> half = fibonacciKeys(sphere.mesh, voxels, 500000);
    EXPECT_GE(voxels.shareSeen(half).area, 0.999);
    std::vector<std::uint64_t> million = fibonacciKeys(sphere.mesh, voxels, 1000000);
    const SurfaceShare share = voxels.shareSeen(million);
    EXPECT_GE(share.area, 0.9995);
    EXPECT_LT(share.voxels, 0.99);
    // The bound spreads the points over each triangle alone: nearly as even.
    EXPECT_GE(evenSamplingBound(sphere.mesh, voxels, 1000000), 0.999);
    const double quarter = evenSamplingBound(sphere.mesh, voxels, 250000);
    EXPECT_GT(quarter, 0.99);
    EXPECT_LT(quarter, 0.999);
}

}  // namespace
}  // namespace ivis::optimize
