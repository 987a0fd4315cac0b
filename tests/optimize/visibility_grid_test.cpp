// The visibility measure's marked voxels and its ceiling, against brute force on a flat square
// whose marked shell is two voxels thick while the square crosses only one layer of it.
#include <ivis/core/triangle_bvh.h>
#include <ivis/optimize/visibility_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {
namespace {

TEST(VisibilityGrid, MarkedAndSurfaceVoxelsOfASquareMatchBruteForce)
{
    const float lo = -0.4901f, hi = 0.5103f, z = 0.0155f;  // off the voxel boundaries
    core::TriangleMesh square;
    square.positions = {{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    square.dataTriangleCount = 2;
    const core::TriangleBvh bvh(square);
    const VisibilityGrid grid(square, bvh, 200);
    const double vs = grid.voxelSize();
    std::size_t marked = 0, crossed = 0;
    for (int k = 0; k < 200; ++k)
        for (int j = 0; j < 200; ++j)
            for (int i = 0; i < 200; ++i) {
                const double x = -2.5 + (i + 0.5) * vs, y = -2.5 + (j + 0.5) * vs, c = -2.5 + (k + 0.5) * vs;
                const double dx = std::max({lo - x, 0.0, x - hi}), dy = std::max({lo - y, 0.0, y - hi});
                if (dx * dx + dy * dy + (c - z) * (c - z) >= vs * vs) continue;
                ++marked;
                const bool inLayer = std::abs(c - z) <= 0.5 * vs;
                const bool overlaps = x + 0.5 * vs >= lo && x - 0.5 * vs <= hi && y + 0.5 * vs >= lo && y - 0.5 * vs <= hi;
                crossed += inLayer && overlaps;
            }
    EXPECT_EQ(grid.markedCount(), marked);
    EXPECT_EQ(SurfaceVoxels(square, 200).count(), crossed);
    EXPECT_LT(double(crossed), 0.55 * double(marked)) << "the square crosses about half its marked shell";
}

}  // namespace
}  // namespace ivis::optimize
