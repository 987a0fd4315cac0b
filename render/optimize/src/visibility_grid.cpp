#include <ivis/optimize/visibility_grid.h>

#include <ivis/core/errors.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>

namespace ivis::optimize {

VisibilityGrid::VisibilityGrid(const core::TriangleMesh& mesh, const core::TriangleBvh& bvh, int resolution)
    : mLattice{resolution}
{
    if (resolution < 8 || resolution > 8192)
        throw ValueError("visibility grid resolution " + std::to_string(resolution) + " is out of range (8 to 8192)");
    // Candidates: voxels whose centre lies in a triangle's box grown by one voxel, gathered and
    // deduplicated per run of triangles (neighbours in a mesh's order share most of theirs: a
    // 1.6M-triangle mesh gave 43M candidates with repeats), then merged.
    constexpr std::size_t kTrianglesPerRun = 4096;
    const std::size_t runs = (mesh.triangles.size() + kTrianglesPerRun - 1) / kTrianglesPerRun;
    std::vector<std::vector<std::uint64_t>> perRun(runs);
    const double voxelSize = mLattice.voxelSize();
    tbb::parallel_for(std::size_t(0), runs, [&](std::size_t run) {
        std::vector<std::uint64_t>& keys = perRun[run];
        const std::size_t end = std::min(mesh.triangles.size(), (run + 1) * kTrianglesPerRun);
        for (std::size_t t = run * kTrianglesPerRun; t < end; ++t) {
            glm::dvec3 lo(1e30), hi(-1e30);
            for (std::uint32_t v : mesh.triangles[t]) {
                lo = glm::min(lo, glm::dvec3(mesh.positions[v]));
                hi = glm::max(hi, glm::dvec3(mesh.positions[v]));
            }
            int i0[3], i1[3];
            for (int a = 0; a < 3; ++a) {
                i0[a] = std::max(0, int(std::ceil(mLattice.indexFromWorld(lo[a] - voxelSize))));
                i1[a] = std::min(resolution - 1, int(std::floor(mLattice.indexFromWorld(hi[a] + voxelSize))));
            }
            for (int k = i0[2]; k <= i1[2]; ++k)
                for (int j = i0[1]; j <= i1[1]; ++j)
                    for (int i = i0[0]; i <= i1[0]; ++i)
                        keys.push_back((std::uint64_t(k) * resolution + j) * resolution + i);
        }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    });
    std::vector<std::uint64_t> candidates;
    for (const auto& keys : perRun) candidates.insert(candidates.end(), keys.begin(), keys.end());
    tbb::parallel_sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    std::vector<char> marked(candidates.size(), 0);
    tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t n) {
        const std::uint64_t key = candidates[n];
        const glm::dvec3 centre(mLattice.worldFromIndex(double(key % resolution)),
                                mLattice.worldFromIndex(double(key / resolution % resolution)),
                                mLattice.worldFromIndex(double(key / (std::uint64_t(resolution) * resolution))));
        int triangle = -1;
        const core::TrianglePoint closest = bvh.closestPoint(centre, voxelSize, triangle);
        marked[n] = triangle >= 0 && closest.distanceSquared < voxelSize * voxelSize;
    });
    for (std::size_t n = 0; n < candidates.size(); ++n)
        if (marked[n]) mMarked.push_back(candidates[n]);
}

double VisibilityGrid::fractionVisited(std::vector<std::uint64_t>& keys) const
{
    return mMarked.empty() ? 0.0 : double(countMarked(keys)) / double(mMarked.size());
}

std::size_t VisibilityGrid::countMarked(std::vector<std::uint64_t>& keys) const { return countIn(mMarked, keys); }

}  // namespace ivis::optimize
