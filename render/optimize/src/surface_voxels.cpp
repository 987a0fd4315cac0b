#include <ivis/optimize/surface_voxels.h>

#include <ivis/core/errors.h>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {

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
    std::vector<std::vector<std::uint64_t>> perTriangle(mesh.triangles.size());
    const double spacing = mLattice.voxelSize() / 8.0;
    tbb::parallel_for(std::size_t(0), mesh.triangles.size(), [&](std::size_t t) {
        const glm::vec3 a = mesh.positions[mesh.triangles[t][0]], b = mesh.positions[mesh.triangles[t][1]],
                        c = mesh.positions[mesh.triangles[t][2]];
        const double longest = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
        const int n = std::max(1, int(std::ceil(longest / spacing)));
        std::vector<std::uint64_t>& keys = perTriangle[t];
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const float u = float(i) / n, v = float(j) / n;
                if (keep && !keep(t, glm::vec3(1.0f - u - v, u, v))) continue;
                const std::uint64_t key = keyOf(a + u * (b - a) + v * (c - a));
                if (key != kNoVoxel) keys.push_back(key);
            }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    });
    for (const auto& keys : perTriangle) mKeys.insert(mKeys.end(), keys.begin(), keys.end());
    tbb::parallel_sort(mKeys.begin(), mKeys.end());
    mKeys.erase(std::unique(mKeys.begin(), mKeys.end()), mKeys.end());
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

double SurfaceVoxels::fractionSeen(std::vector<std::uint64_t>& keys) const
{
    return mKeys.empty() ? 0.0 : double(countAmong(keys)) / double(mKeys.size());
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
