// Surface voxels against brute force: regions, filters and keys of a pair of squares.
#include <ivis/optimize/surface_voxels.h>

#include <gtest/gtest.h>

namespace ivis::optimize {
namespace {

/// Two squares in the plane z = 0.0155, [-0.49, -0.09] and [0.31, 0.71] in x, [-0.2, 0.2] in y:
/// separated by more than a voxel at resolution 200 (voxel 0.025).
///   3---2   7---6
///   |   |   |   |
///   0---1   4---5
core::TriangleMesh twoSquares()
{
    core::TriangleMesh mesh;
    const float z = 0.0155f;
    for (float x0 : {-0.4901f, 0.3102f})
        for (auto [x, y] : {std::pair{0.0f, -0.2f}, {0.4f, -0.2f}, {0.4f, 0.2f}, {0.0f, 0.2f}})
            mesh.positions.push_back({x0 + x, y, z});
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    mesh.dataTriangleCount = 4;
    return mesh;
}

TEST(SurfaceVoxels, SquaresCoverTheVoxelsTheyCrossAndSplitIntoTwoRegions)
{
    const core::TriangleMesh mesh = twoSquares();
    const SurfaceVoxels voxels(mesh, 200);
    // Brute force: the voxels of the squares' layer whose cell [x0, x1) x [y0, y1) meets a square
    // (a point on a face belongs to the voxel above it).
    std::size_t brute = 0;
    const double yLo = double(-0.2f), yHi = double(0.2f);
    const vdb::BoxLattice lattice{200};
    for (int j = 0; j < 200; ++j)
        for (int i = 0; i < 200; ++i) {
            const double x0 = lattice.worldFromIndex(double(i)) - 0.0125, x1 = x0 + 0.025;
            const double y0 = lattice.worldFromIndex(double(j)) - 0.0125, y1 = y0 + 0.025;
            for (float lo : {-0.4901f, 0.3102f})
                brute += x1 > lo && x0 <= double(lo + 0.4f) && y1 > yLo && y0 <= yHi ? 1 : 0;
        }
    EXPECT_EQ(voxels.count(), brute);
    const auto regions = voxels.regions();
    ASSERT_EQ(regions.size(), 2u);
    EXPECT_EQ(regions[0].size() + regions[1].size(), voxels.count());

    const SurfaceVoxels left(mesh, 200, [](std::size_t triangle, const glm::vec3&) { return triangle < 2; });
    EXPECT_EQ(left.count(), regions[0].size());
    std::vector<std::uint64_t> seen = left.keys();
    EXPECT_DOUBLE_EQ(voxels.fractionSeen(seen), 0.5);
    std::vector<std::uint64_t> outside{voxelKey(lattice, glm::vec3(3.0f, 0.0f, 0.0f))};
    EXPECT_EQ(outside[0], kNoVoxel);
    EXPECT_EQ(voxels.countAmong(outside), 0u);
}

}  // namespace
}  // namespace ivis::optimize
