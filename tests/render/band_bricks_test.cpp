// BandBricks against the sparse grids they are built from: every corner of every fine cell of the
// unit sphere's band (resolution 100) read from its brick equals the grids' value, or is NaN where
// the grids have no active voxel; cells without a leaf have no brick.
#include "render/scene_fixture.h"

#include <ivis/render/band_bricks.h>

#include <gtest/gtest.h>

#include <cmath>

namespace ivis::render {
namespace {

TEST(BandBricks, EveryCellsCornersAreTheGridsVoxels)
{
    const vdb::SurfaceVolume& volume = test::sphereWithFarField().volume;
    const BandBricks bricks(*volume.phi, *volume.gradient);
    auto phi = volume.phi->getConstAccessor();
    auto gradient = volume.gradient->getConstAccessor();
    const openvdb::CoordBBox box = volume.phi->evalActiveVoxelBoundingBox();
    ASSERT_GE(box.min().x(), 0);  // the sampler's index space: non-negative inside the volume's box
    int cellsWithBrick = 0, activeCorners = 0, inactiveCorners = 0;
    for (int z = box.min().z() - 1; z <= box.max().z(); ++z)
        for (int y = box.min().y() - 1; y <= box.max().y(); ++y)
            for (int x = box.min().x() - 1; x <= box.max().x(); ++x) {
                const glm::vec4* brick = bricks.find(x, y, z);
                const bool hasLeaf = phi.probeConstLeaf(openvdb::Coord(x, y, z)) != nullptr;
                ASSERT_EQ(brick != nullptr, hasLeaf) << x << " " << y << " " << z;
                if (!brick) continue;
                ++cellsWithBrick;
                for (int i = 0; i < 8; ++i) {
                    const int dx = i & 1, dy = (i >> 1) & 1, dz = (i >> 2) & 1;
                    const openvdb::Coord ijk(x + dx, y + dy, z + dz);
                    const glm::vec4 voxel = brick[BandBricks::voxelOffset((x & 7) + dx, (y & 7) + dy, (z & 7) + dz)];
                    float value;
                    if (!phi.probeValue(ijk, value)) {
                        ++inactiveCorners;
                        ASSERT_TRUE(std::isnan(voxel.x)) << ijk;
                        continue;
                    }
                    ++activeCorners;
                    const openvdb::Vec3s g = gradient.getValue(ijk);
                    ASSERT_EQ(voxel, glm::vec4(value, g.x(), g.y(), g.z())) << ijk;
                }
            }
    EXPECT_GT(cellsWithBrick, 10000);
    EXPECT_GT(activeCorners, 10000);
    EXPECT_GT(inactiveCorners, 1000);  // the band's edges and the leaves' empty corners
}

}  // namespace
}  // namespace ivis::render
