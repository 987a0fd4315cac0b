// BoxLattice: voxel centres span [-2.5, 2.5], index <-> world round trips, the voxel containing a
// point, and agreement with the OpenVDB transform it makes and with the grids of a built volume.
#include "brute_force.h"

#include <ivis/core/procedural_scenes.h>
#include <ivis/vdb/box_lattice.h>
#include <ivis/vdb/surface_volume.h>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace ivis::vdb {
namespace {

TEST(BoxLattice, VoxelCentresSpanTheBox)
{
    for (const int resolution : {16, 100, 200, 1000}) {
        const BoxLattice lattice{resolution};
        const double size = lattice.voxelSize();
        EXPECT_NEAR(size * resolution, 5.0, 1e-12);
        EXPECT_NEAR(lattice.worldFromIndex(0.0), -2.5 + 0.5 * size, 1e-12);
        EXPECT_NEAR(lattice.worldFromIndex(resolution - 1.0), 2.5 - 0.5 * size, 1e-12);
        EXPECT_NEAR(lattice.worldFromIndex(-0.5), -2.5, 1e-12) << "the box starts at the first voxel's face";
        for (const int i : {0, 1, resolution / 2, resolution - 1})
            EXPECT_NEAR(lattice.worldFromIndex(i + 1.0) - lattice.worldFromIndex(double(i)), size, 1e-12);
    }
}

TEST(BoxLattice, IndexAndWorldRoundTrip)
{
    const BoxLattice lattice{200};
    for (double i = -3.0; i <= 203.0; i += 0.37) {
        EXPECT_NEAR(lattice.indexFromWorld(lattice.worldFromIndex(i)), i, 1e-9);
        EXPECT_NEAR(lattice.cellFromWorld(lattice.worldFromIndex(i)), i + 0.5, 1e-9);
    }
    for (double x = -2.6; x <= 2.6; x += 0.013)
        EXPECT_NEAR(lattice.worldFromIndex(lattice.indexFromWorld(x)), x, 1e-12);
    for (int i = 0; i < 200; ++i) {
        // The voxel containing a point: its centre, and points just inside its faces.
        const double centre = lattice.worldFromIndex(double(i)), half = 0.499 * lattice.voxelSize();
        for (const double x : {centre, centre - half, centre + half})
            EXPECT_EQ(std::floor(lattice.cellFromWorld(x)), double(i)) << "x " << x;
    }
}

TEST(BoxLattice, CoordCentresAgreeWithAxisCentresAndTheTransform)
{
    const BoxLattice lattice{160};
    const auto transform = lattice.transform();
    for (int i = -2; i < 163; i += 3) {
        const openvdb::Coord ijk(i, 160 - i, i / 2);
        const openvdb::Vec3d centre = lattice.worldFromIndex(ijk);
        EXPECT_EQ(transform->indexToWorld(ijk), centre) << "the transform computes the same bits";
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(centre[a], lattice.worldFromIndex(double(ijk[a])), 1e-14);
        const openvdb::Vec3d back = transform->worldToIndex(centre);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(back[a], ijk[a], 1e-9);
            EXPECT_NEAR(lattice.indexFromWorld(centre[a]), ijk[a], 1e-9);
        }
    }
}

TEST(BoxLattice, BuiltVolumeGridsLieOnTheirLattices)
{
    VolumeOptions options;
    options.resolution = 64;
    options.farFieldResolution = 32;
    const core::SurfaceField sphere = core::makeSphere(3);
    const SurfaceVolume volume = buildSurfaceVolume(sphere.mesh, options);
    ASSERT_TRUE(volume.farPhi);
    EXPECT_EQ(volume.lattice().resolution, 64);
    EXPECT_EQ(volume.farLattice().resolution, 32);
    const std::pair<const openvdb::GridBase*, BoxLattice> grids[] = {
        {volume.phi.get(), volume.lattice()},
        {volume.triangle.get(), volume.lattice()},
        {volume.gradient.get(), volume.lattice()},
        {volume.farPhi.get(), volume.farLattice()}};
    for (const auto& [grid, lattice] : grids) {
        // OpenVDB may store the scale a few ulps off (seen: 0.024999999999999911 for 0.025).
        EXPECT_NEAR(grid->voxelSize()[0], lattice.voxelSize(), 1e-14) << grid->getName();
        for (const openvdb::Coord ijk : {openvdb::Coord(0, 0, 0), openvdb::Coord(5, 31, 17), openvdb::Coord(63, 1, 40)}) {
            const openvdb::Vec3d expected = lattice.worldFromIndex(ijk), actual = grid->indexToWorld(ijk);
            for (int a = 0; a < 3; ++a) EXPECT_NEAR(actual[a], expected[a], 1e-12) << grid->getName();
        }
    }
    // Band values are exact distances from the lattice's voxel centres (every 5th voxel checked).
    const test::BruteForceClosest brute(sphere.mesh);
    int checked = 0, index = 0;
    for (auto voxel = volume.phi->cbeginValueOn(); voxel; ++voxel) {
        if (index++ % 5 != 0) continue;
        const openvdb::Vec3d centre = volume.lattice().worldFromIndex(voxel.getCoord());
        const double distance = std::sqrt(brute.closest(glm::dvec3(centre.x(), centre.y(), centre.z())).distanceSquared);
        EXPECT_NEAR(std::abs(*voxel), distance, 1e-6) << voxel.getCoord();
        ++checked;
    }
    EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace ivis::vdb
