#include <ivis/core/errors.h>
#include <ivis/core/surface_field.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ivis::core {
namespace {

/// Two triangles spanning the box [1,5] x [2,3] x [0,1] (x is the longest side, 4 units):
///   0 = (1,2,0)  1 = (5,2,0)  2 = (5,3,1)  3 = (1,3,1)   triangles 0-1-2, 0-2-3
SurfaceField boxField()
{
    SurfaceField field;
    field.mesh.positions = {{1, 2, 0}, {5, 2, 0}, {5, 3, 1}, {1, 3, 1}};
    field.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    field.mesh.dataTriangleCount = 2;
    field.sourcePath = "generated:box";
    return field;
}

TEST(SurfaceField, NormalizeMapsLongestSideToMinusOneOne)
{
    SurfaceField field = boxField();
    const std::vector<glm::vec3> original = field.mesh.positions;
    normalize(field);

    const Bounds3 b = bounds(field.mesh);
    EXPECT_DOUBLE_EQ(b.lo.x, -1.0);
    EXPECT_DOUBLE_EQ(b.hi.x, 1.0);
    EXPECT_DOUBLE_EQ(b.lo.y, -0.25);  // 1 unit of 4, centred
    EXPECT_DOUBLE_EQ(b.hi.y, 0.25);
    EXPECT_DOUBLE_EQ(b.lo.z, -0.25);
    EXPECT_DOUBLE_EQ(b.hi.z, 0.25);
    EXPECT_EQ(field.normalization.center, glm::dvec3(3.0, 2.5, 0.5));
    EXPECT_DOUBLE_EQ(field.normalization.scale, 0.5);
    EXPECT_DOUBLE_EQ(field.normalization.meshLength(2.0), 4.0);

    for (std::size_t i = 0; i < original.size(); ++i) {
        const glm::dvec3 back = field.normalization.meshFromNormalized(glm::dvec3(field.mesh.positions[i]));
        EXPECT_NEAR(back.x, original[i].x, 1e-6);
        EXPECT_NEAR(back.y, original[i].y, 1e-6);
        EXPECT_NEAR(back.z, original[i].z, 1e-6);
        const glm::dvec3 there = field.normalization.normalizedFromMesh(glm::dvec3(original[i]));
        EXPECT_NEAR(there.x, field.mesh.positions[i].x, 1e-6);
    }
}

TEST(SurfaceField, NormalizeTwiceKeepsTheMapToFileUnits)
{
    SurfaceField field = boxField();
    const std::vector<glm::vec3> original = field.mesh.positions;
    normalize(field);
    field.mesh.positions[2] *= 3.0f;  // grow the box so the second call changes something
    const glm::dvec3 grownFile = field.normalization.meshFromNormalized(glm::dvec3(field.mesh.positions[2]));
    normalize(field);
    const glm::dvec3 back = field.normalization.meshFromNormalized(glm::dvec3(field.mesh.positions[2]));
    EXPECT_NEAR(back.x, grownFile.x, 1e-5);
    EXPECT_NEAR(back.y, grownFile.y, 1e-5);
    const glm::dvec3 first = field.normalization.meshFromNormalized(glm::dvec3(field.mesh.positions[0]));
    EXPECT_NEAR(first.x, original[0].x, 1e-5);
    EXPECT_NEAR(first.y, original[0].y, 1e-5);
}

TEST(SurfaceField, NormalizeRejectsZeroExtent)
{
    SurfaceField field;
    field.mesh.positions.assign(3, glm::vec3(2.0f));
    field.mesh.triangles = {{0, 1, 2}};
    EXPECT_THROW(normalize(field), ValueError);
    SurfaceField empty;
    EXPECT_THROW(normalize(empty), ValueError);
}

TEST(SurfaceField, FiniteRangeIgnoresNanAndInfinity)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const auto [lo, hi] = finiteRange({nan, 3.0f, -2.0f, inf, 7.5f, -inf});
    EXPECT_EQ(lo, -2.0f);
    EXPECT_EQ(hi, 7.5f);
    EXPECT_EQ(finiteRange({nan, nan}), std::make_pair(0.0f, 0.0f));
    EXPECT_EQ(finiteRange({}), std::make_pair(0.0f, 0.0f));
    EXPECT_EQ(finiteRange({4.0f}), std::make_pair(4.0f, 4.0f));
}

TEST(SurfaceField, ScalarAtBlendsVertexValuesOrTakesTheCellValue)
{
    SurfaceField field = boxField();
    field.mesh.positions.emplace_back(9, 9, 9);  // a cap: vertex 4, triangle 2
    field.mesh.triangles.push_back({0, 1, 4});
    EXPECT_TRUE(std::isnan(scalarAt(field, 0, glm::vec3(1, 0, 0))));  // no scalar yet

    field.values = {1, 2, 4, 8, 0};
    const glm::vec3 w(0.5f, 0.25f, 0.25f);
    EXPECT_FLOAT_EQ(scalarAt(field, 0, w), 0.5f * 1 + 0.25f * 2 + 0.25f * 4);
    EXPECT_FLOAT_EQ(scalarAt(field, 1, w), 0.5f * 1 + 0.25f * 4 + 0.25f * 8);
    EXPECT_EQ(cornerScalars(field, 1), (std::array<float, 3>{1, 4, 8}));
    EXPECT_TRUE(std::isnan(scalarAt(field, 2, w)));

    field.values = {3, -5};
    field.valuesOn = Association::Cell;
    EXPECT_EQ(scalarAt(field, 0, w), 3.0f);
    EXPECT_EQ(scalarAt(field, 1, glm::vec3(0, 0, 1)), -5.0f);
    EXPECT_EQ(cornerScalars(field, 1), (std::array<float, 3>{-5, -5, -5}));
    EXPECT_TRUE(std::isnan(scalarAt(field, 2, w)));
}

}  // namespace
}  // namespace ivis::core
