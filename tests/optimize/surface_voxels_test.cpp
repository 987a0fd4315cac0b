// Surface voxels against brute force: regions, filters and keys of a pair of squares; the area
// inside each voxel against the exact share of a half-seen quad and against random points.
#include <ivis/optimize/surface_voxels.h>
#include <ivis/optimize/voxel_pieces.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

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
    EXPECT_NEAR(left.totalArea(), 0.16, 1e-6);
    EXPECT_NEAR(voxels.totalArea(), 0.32, 1e-6);
    std::vector<std::uint64_t> seen = left.keys();
    const SurfaceShare share = voxels.shareSeen(seen);
    EXPECT_DOUBLE_EQ(share.voxels, 0.5);
    EXPECT_NEAR(share.area, 0.5, 1e-9);
    std::vector<std::uint64_t> outside{voxelKey(lattice, glm::vec3(3.0f, 0.0f, 0.0f))};
    EXPECT_EQ(outside[0], kNoVoxel);
    EXPECT_EQ(voxels.countAmong(outside), 0u);
    EXPECT_EQ(voxels.shareSeen(outside).area, 0.0);
}

TEST(SurfaceVoxels, AHalfSeenTiltedQuadMeasuresItsSeenAreaShare)
{
    // A quad over [x0, x1] x [y0, y1] on a tilted plane, not aligned with the voxels: the area of
    // its part with x below a voxel boundary X is (X - x0) / (x1 - x0) of its area, exactly.
    const float x0 = -0.4137f, x1 = 0.5021f, y0 = -0.3311f, y1 = 0.2793f;
    auto z = [](float x, float y) { return 0.05f + 0.6f * x - 0.35f * y; };
    core::TriangleMesh quad;
    quad.positions = {{x0, y0, z(x0, y0)}, {x1, y0, z(x1, y0)}, {x1, y1, z(x1, y1)}, {x0, y1, z(x0, y1)}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.dataTriangleCount = 2;
    const SurfaceVoxels voxels(quad, 200);
    const double tilt = std::sqrt(1.0 + 0.6 * 0.6 + 0.35 * 0.35);
    EXPECT_NEAR(voxels.totalArea(), double(x1 - x0) * double(y1 - y0) * tilt, 1e-6);

    const vdb::BoxLattice& lattice = voxels.lattice();
    for (int boundary : {90, 100, 111}) {  // cell planes inside the quad's x range
        std::vector<std::uint64_t> seen;
        for (std::uint64_t key : voxels.keys())
            if (int(key % 200) < boundary) seen.push_back(key);
        const double X = -2.5 + boundary * lattice.voxelSize();
        EXPECT_NEAR(voxels.shareSeen(seen).area, (X - x0) / double(x1 - x0), 1e-6) << boundary;
    }
}

TEST(VoxelPieces, PiecesTileTheTriangleAsRandomPointsFallIntoTheVoxels)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, 6.0), unit(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const glm::dvec3 a(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec3 b(coordinate(random), coordinate(random), coordinate(random));
        const glm::dvec3 c(coordinate(random), coordinate(random), coordinate(random));
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        std::map<std::tuple<int, int, int>, double> pieces;
        double sum = 0.0;
        cutIntoVoxels(a, b, c, [&](const glm::ivec3& v, const ConvexPiece& piece) {
            for (int i = 0; i < piece.size; ++i)  // the piece lies in its voxel
                for (int axis = 0; axis < 3; ++axis) {
                    EXPECT_GE(piece.corners[std::size_t(i)][axis], v[axis] - 1e-9);
                    EXPECT_LE(piece.corners[std::size_t(i)][axis], v[axis] + 1 + 1e-9);
                }
            pieces[{v.x, v.y, v.z}] += pieceArea(piece);
            sum += pieceArea(piece);
        });
        EXPECT_NEAR(sum, area, 1e-9 * area) << trial;
        // Brute force: uniform points on the triangle counted per voxel.
        const int points = 200000;
        std::map<std::tuple<int, int, int>, int> hits;
        for (int i = 0; i < points; ++i) {
            double u = unit(random), v = unit(random);
            if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
            const glm::dvec3 p = a + u * (b - a) + v * (c - a);
            ++hits[{int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z))}];
        }
        for (const auto& [voxel, count] : hits) {
            const double share = double(count) / points, expected = pieces[voxel] / area;
            EXPECT_NEAR(share, expected, 5.0 * std::sqrt(expected * (1.0 - expected) / points) + 1e-4) << trial;
        }
    }
}

}  // namespace
}  // namespace ivis::optimize
