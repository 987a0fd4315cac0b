// The view set's greedy choice against brute force on hand-made views of two squares: the best view
// first, then the view adding the most area (not the one seeing the most), none that adds nothing.
#include <ivis/core/errors.h>
#include <ivis/optimize/view_set.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace ivis::optimize {
namespace {

/// A 0.4 x 0.4 square and a 0.2 x 0.4 one in the plane z = 0.0155, far apart.
core::TriangleMesh twoSquares()
{
    core::TriangleMesh mesh;
    const float z = 0.0155f;
    for (auto [x0, width] : {std::pair{-0.4901f, 0.4f}, {0.3102f, 0.2f}})
        for (auto [x, y] : {std::pair{0.0f, -0.2f}, {width, -0.2f}, {width, 0.2f}, {0.0f, 0.2f}})
            mesh.positions.push_back({x0 + x, y, z});
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    mesh.dataTriangleCount = 4;
    return mesh;
}

/// A visited view that sees the voxels of @a voxels whose x index lies in [lo, hi).
VisitedView seeing(const SurfaceVoxels& voxels, int lo, int hi)
{
    VisitedView view;
    for (std::uint64_t key : voxels.keys())
        if (int(key % 200) >= lo && int(key % 200) < hi) view.value.seenVoxels.push_back(key);
    return view;
}

TEST(ViewSet, AddsTheViewThatAddsTheMostAreaAndStopsWhenNoneAddsAny)
{
    const core::TriangleMesh mesh = twoSquares();
    const SurfaceVoxels voxels(mesh, 200);
    // The big square spans x cells 80-96, the small one 112-120 (voxel 0.025, box from -2.5).
    const std::vector<VisitedView> views = {
        seeing(voxels, 80, 90),    // 0: most of the big square
        seeing(voxels, 84, 97),    // 1: the most area alone, but mostly what 0 sees
        seeing(voxels, 110, 125),  // 2: the small square, whole
        seeing(voxels, 90, 97),    // 3: the rest of the big square
        seeing(voxels, 0, 10),     // 4: nothing
    };
    // Brute force over the pairs with view 0: the union's area.
    auto unionArea = [&](std::vector<std::size_t> set) {
        std::vector<std::uint64_t> keys;
        for (std::size_t v : set) keys.insert(keys.end(), views[v].value.seenVoxels.begin(), views[v].value.seenVoxels.end());
        return voxels.shareSeen(keys).area;
    };
    std::size_t bestSecond = 1;
    for (std::size_t v = 1; v < views.size(); ++v)
        if (unionArea({0, v}) > unionArea({0, bestSecond})) bestSecond = v;
    const std::vector<std::size_t> two = chooseViewSet(views, 0, voxels, 2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0], 0u);
    EXPECT_EQ(two[1], bestSecond);
    EXPECT_EQ(two[1], 2u) << "the small square adds more than the big square's rest";

    const std::vector<std::size_t> all = chooseViewSet(views, 0, voxels, 5);
    // Views 1 and 3 then add the same area, the big square's rest: the earlier one; then none adds any.
    EXPECT_EQ(all, (std::vector<std::size_t>{0, 2, 1}));
    EXPECT_NEAR(unionArea(all), 1.0, 1e-12);
    EXPECT_THROW(chooseViewSet(views, 0, voxels, 0), ValueError);
    EXPECT_THROW(chooseViewSet(views, 5, voxels, 2), ValueError);
}

}  // namespace
}  // namespace ivis::optimize
