// The even-sampling bound of the surface visibility: a flat square without grazed voxels is seen
// whole by enough points and by no more voxels than points; on the unit sphere, whose grazed
// voxels hold little of its area, a million points miss a few percent and four million almost none.
#include <ivis/optimize/sampling_bound.h>

#include <ivis/core/errors.h>
#include <ivis/core/procedural_scenes.h>

#include <gtest/gtest.h>

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
    for (std::size_t samples : {1, 10, 64, 200})
        EXPECT_LE(evenSamplingBound(square, voxels, samples), double(samples) / 256.0) << samples;
    EXPECT_GT(evenSamplingBound(square, voxels, 64), 0.15);  // spread, not clumped in a corner
    EXPECT_THROW(evenSamplingBound(square, voxels, 0), ValueError);
}

TEST(SamplingBound, TheUnitSpheresGrazedVoxelsKeepAMillionPointsBelowOne)
{
    // An independent even spread (Fibonacci points on the exact sphere) sees about 95% of the
    // voxels the exact sphere meets with a million points; those include 4% more than the
    // icosphere's, which the sphere only touches at a corner or an edge and no point can hit.
    const core::SurfaceField sphere = core::makeSphere(5);
    const SurfaceVoxels voxels(sphere.mesh, 200);
    const double million = evenSamplingBound(sphere.mesh, voxels, 1000000);
    EXPECT_GT(million, 0.95);
    EXPECT_LT(million, 0.99);
    EXPECT_GT(evenSamplingBound(sphere.mesh, voxels, 4000000), million + 0.01);
}

}  // namespace
}  // namespace ivis::optimize
