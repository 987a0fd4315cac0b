#include <ivis/optimize/surface_voxels.h>

#include <ivis/core/errors.h>
#include <ivis/optimize/voxel_pieces.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ivis::optimize {
namespace {

/// Barycentric weights (of a, b, c) of @a p in the plane of the triangle @a a, @a b, @a c.
glm::vec3 barycentricOf(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 e0 = b - a, e1 = c - a, d = p - a;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double d20 = glm::dot(d, e0), d21 = glm::dot(d, e1), denominator = d00 * d11 - d01 * d01;
    const double u = (d11 * d20 - d01 * d21) / denominator, v = (d00 * d21 - d01 * d20) / denominator;
    return glm::vec3(float(1.0 - u - v), float(u), float(v));
}

/// The share of @a piece that @a keep accepts at 16 even points of each of its fan's triangles
/// (the centroids of the triangles of a 4 x 4 subdivision), weighted by area; in [0, 1].
double keptShare(const ConvexPiece& piece, std::size_t triangle, const glm::dvec3 (&corners)[3], const SampleFilter& keep)
{
    constexpr int kSteps = 4;
    double kept = 0.0, total = 0.0;
    for (int f = 1; f + 1 < piece.size; ++f) {
        const glm::dvec3 o = piece.corners[0], e0 = piece.corners[std::size_t(f)] - o, e1 = piece.corners[std::size_t(f + 1)] - o;
        const double area = 0.5 * glm::length(glm::cross(e0, e1));
        int accepted = 0;
        auto test = [&](double u, double v) {
            accepted += keep(triangle, barycentricOf(o + (u / kSteps) * e0 + (v / kSteps) * e1, corners[0], corners[1], corners[2])) ? 1 : 0;
        };
        for (int i = 0; i < kSteps; ++i)
            for (int j = 0; i + j < kSteps; ++j) {
                test(i + 1.0 / 3.0, j + 1.0 / 3.0);                             // the upward triangles
                if (i + j + 2 <= kSteps) test(i + 2.0 / 3.0, j + 2.0 / 3.0);  // the downward ones
            }
        kept += area * accepted / double(kSteps * kSteps);
        total += area;
    }
    return total > 0.0 ? kept / total : 0.0;
}

}  // namespace

std::uint64_t voxelKey(const vdb::BoxLattice& lattice, const glm::vec3& p)
{
    std::uint64_t index[3];
    for (int a = 0; a < 3; ++a) {
        const double i = std::floor(lattice.cellFromWorld(double(p[a])));
        if (!(i >= 0.0 && i < lattice.resolution)) return kNoVoxel;
        index[a] = std::uint64_t(i);
    }
    const std::uint64_t n = std::uint64_t(lattice.resolution);
    return (index[2] * n + index[1]) * n + index[0];
}

SurfaceVoxels::SurfaceVoxels(const core::TriangleMesh& mesh, int resolution, const SampleFilter& keep)
    : mLattice{resolution}
{
    if (resolution < 8 || resolution > 8192)
        throw ValueError("visibility grid resolution " + std::to_string(resolution) + " is out of range (8 to 8192)");
    std::vector<std::vector<std::pair<std::uint64_t, double>>> piecesPerTriangle(mesh.triangles.size());
    const double voxelFace = mLattice.voxelSize() * mLattice.voxelSize();
    const int side = mLattice.resolution;
    tbb::parallel_for(std::size_t(0), mesh.triangles.size(), [&](std::size_t t) {
        glm::dvec3 cells[3];
        for (int corner = 0; corner < 3; ++corner)
            for (int axis = 0; axis < 3; ++axis)
                cells[corner][axis] = mLattice.cellFromWorld(double(mesh.positions[mesh.triangles[t][std::size_t(corner)]][axis]));
        cutIntoVoxels(cells[0], cells[1], cells[2], [&](const glm::ivec3& voxel, const ConvexPiece& piece) {
            for (int axis = 0; axis < 3; ++axis)
                if (voxel[axis] < 0 || voxel[axis] >= side) return;
            double area = pieceArea(piece) * voxelFace;
            if (keep && area > 0.0) area *= keptShare(piece, t, cells, keep);
            if (area > 0.0)
                piecesPerTriangle[t].emplace_back((std::uint64_t(voxel.z) * std::uint64_t(side) + std::uint64_t(voxel.y)) * std::uint64_t(side) + std::uint64_t(voxel.x), area);
        });
    });
    // Sorted by key and area together, a total order: the sums do not depend on the threads.
    std::vector<std::pair<std::uint64_t, double>> pieces;
    for (const auto& triangle : piecesPerTriangle) pieces.insert(pieces.end(), triangle.begin(), triangle.end());
    tbb::parallel_sort(pieces.begin(), pieces.end());
    for (const auto& [key, area] : pieces) {
        if (mKeys.empty() || mKeys.back() != key) {
            mKeys.push_back(key);
            mAreas.push_back(0.0);
        }
        mAreas.back() += area;
    }
    for (double area : mAreas) mTotalArea += area;
}

std::size_t countIn(const std::vector<std::uint64_t>& set, std::vector<std::uint64_t>& keys)
{
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::size_t count = 0;
    for (std::uint64_t key : keys) count += std::binary_search(set.begin(), set.end(), key) ? 1 : 0;
    return count;
}

std::size_t SurfaceVoxels::countAmong(std::vector<std::uint64_t>& keys) const { return countIn(mKeys, keys); }

SurfaceShare SurfaceVoxels::shareSeen(std::vector<std::uint64_t>& keys) const
{
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::size_t count = 0;
    double area = 0.0;
    for (std::uint64_t key : keys) {
        const auto found = std::lower_bound(mKeys.begin(), mKeys.end(), key);
        if (found == mKeys.end() || *found != key) continue;
        ++count;
        area += mAreas[std::size_t(found - mKeys.begin())];
    }
    SurfaceShare share;
    if (!mKeys.empty()) share.voxels = double(count) / double(mKeys.size());
    if (mTotalArea > 0.0) share.area = std::min(1.0, area / mTotalArea);
    return share;
}

double SurfaceVoxels::areaIn(std::uint64_t key) const
{
    const auto found = std::lower_bound(mKeys.begin(), mKeys.end(), key);
    return found != mKeys.end() && *found == key ? mAreas[std::size_t(found - mKeys.begin())] : 0.0;
}

std::vector<std::vector<std::uint64_t>> SurfaceVoxels::regions() const
{
    const std::int64_t n = mLattice.resolution;
    std::vector<char> visited(mKeys.size(), 0);
    std::vector<std::vector<std::uint64_t>> regions;
    for (std::size_t seed = 0; seed < mKeys.size(); ++seed) {
        if (visited[seed]) continue;
        visited[seed] = 1;
        std::vector<std::uint64_t> region{mKeys[seed]};
        for (std::size_t next = 0; next < region.size(); ++next) {
            const std::int64_t key = std::int64_t(region[next]);
            const std::int64_t i = key % n, j = key / n % n, k = key / (n * n);
            for (std::int64_t dk = -1; dk <= 1; ++dk)
                for (std::int64_t dj = -1; dj <= 1; ++dj)
                    for (std::int64_t di = -1; di <= 1; ++di) {
                        const std::int64_t x = i + di, y = j + dj, z = k + dk;
                        if (x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n) continue;
                        const auto found = std::lower_bound(mKeys.begin(), mKeys.end(), std::uint64_t((z * n + y) * n + x));
                        if (found == mKeys.end() || *found != std::uint64_t((z * n + y) * n + x)) continue;
                        const std::size_t index = std::size_t(found - mKeys.begin());
                        if (visited[index]) continue;
                        visited[index] = 1;
                        region.push_back(*found);
                    }
        }
        std::sort(region.begin(), region.end());
        regions.push_back(std::move(region));
    }
    std::stable_sort(regions.begin(), regions.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return regions;
}

}  // namespace ivis::optimize
