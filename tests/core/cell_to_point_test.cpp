#include <ivis/core/cell_to_point.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ivis::core {
namespace {

/// Three triangles in the plane z = 0 and one cap triangle (not data):
///   3 ------- 2        triangle 0: 0-1-2 (area 2), value 1
///   |  1  /   |        triangle 1: 0-2-3 (area 2), value 4
///   |   /  0  |        triangle 2: 1-4-2 (area 1), value NaN
///   0 ------- 1 - 4    triangle 3: 0-1-3, a cap
///   square of side 2; 4 = (3, 0)
TEST(CellToPoint, AreaWeightedMeanOfTheFiniteDataTriangles)
{
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {3, 0, 0}, {9, 9, 9}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}, {0, 1, 3}};
    mesh.dataTriangleCount = 3;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<float> v = cellToPoint(mesh, {1.0f, 4.0f, nan});
    ASSERT_EQ(v.size(), 6u);
    EXPECT_FLOAT_EQ(v[0], 2.5f);  // (2 * 1 + 2 * 4) / 4
    EXPECT_FLOAT_EQ(v[1], 1.0f);  // the NaN triangle does not count
    EXPECT_FLOAT_EQ(v[2], 2.5f);
    EXPECT_FLOAT_EQ(v[3], 4.0f);
    EXPECT_TRUE(std::isnan(v[4]));  // only a NaN triangle around it
    EXPECT_TRUE(std::isnan(v[5]));  // no triangle at all

    // Unequal areas weigh: grow triangle 1 to area 6 by moving 3 to (0, 6) -> 0 = (2 + 6 * 4) / 8.
    mesh.positions[3] = {0, 6, 0};
    EXPECT_FLOAT_EQ(cellToPoint(mesh, {1.0f, 4.0f, nan})[0], 3.25f);
}

}  // namespace
}  // namespace ivis::core
