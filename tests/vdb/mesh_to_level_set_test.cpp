// Volume build against exhaustive closest-point search: distances, signs, triangle IDs and
// distance gradients of every active voxel within the hull distance phi0 = 0.4.
#include "brute_force.h"
#include "test_support.h"

#include <ivis/core/closest_point.h>
#include <ivis/core/errors.h>
#include <ivis/core/hole_capping.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/surface_source.h>
#include <ivis/vdb/surface_volume.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <utility>

namespace ivis::vdb {
namespace {

constexpr double kHullOffset = 0.4;

struct VoxelSample {
    glm::dvec3 position;
    float phi;
    std::int32_t triangle;  // -1 for far-field voxels
    openvdb::Vec3s gradient;
    double voxelSize;
};

/// Active voxels of the fine band within phi0, plus far-field voxels within phi0 outside the band.
std::vector<VoxelSample> samplesWithinHull(const SurfaceVolume& volume)
{
    std::vector<VoxelSample> samples;
    auto triangle = volume.triangle->getConstAccessor();
    auto gradient = volume.gradient->getConstAccessor();
    for (auto it = volume.phi->cbeginValueOn(); it; ++it) {
        if (std::abs(*it) > kHullOffset) continue;
        const openvdb::Vec3d p = volume.phi->indexToWorld(it.getCoord());
        samples.push_back({{p.x(), p.y(), p.z()}, *it, triangle.getValue(it.getCoord()),
                           gradient.getValue(it.getCoord()), volume.voxelSize()});
    }
    if (volume.farPhi) {
        auto fine = volume.phi->getConstAccessor();
        auto farGradient = volume.farGradient->getConstAccessor();
        const double farVoxel = volume.farPhi->voxelSize()[0];
        for (auto it = volume.farPhi->cbeginValueOn(); it; ++it) {
            if (std::abs(*it) > kHullOffset) continue;
            const openvdb::Vec3d p = volume.farPhi->indexToWorld(it.getCoord());
            if (fine.isValueOn(volume.phi->transform().worldToIndexCellCentered(p))) continue;
            samples.push_back({{p.x(), p.y(), p.z()}, *it, -1, farGradient.getValue(it.getCoord()), farVoxel});
        }
    }
    return samples;
}

struct Report {
    std::size_t samples = 0, distanceFailures = 0, signFailures = 0, pointFailures = 0, missingTriangle = 0,
                gradientFailures = 0;
    double worstDistanceErrorVoxels = 0.0;
};

/// Compares every sample with the exhaustive answer.
Report compareWithBruteForce(const core::TriangleMesh& mesh, const SurfaceVolume& volume, bool expectSigned)
{
    const test::BruteForceClosest brute(mesh);
    const std::vector<VoxelSample> samples = samplesWithinHull(volume);
    Report report;
    report.samples = samples.size();
    std::mutex mutex;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size()), [&](const auto& range) {
        Report local;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
            const VoxelSample& s = samples[i];
            const core::TrianglePoint exact = brute.closest(s.position);
            const double distance = std::sqrt(exact.distanceSquared);
            const double error = std::abs(std::abs(double(s.phi)) - distance) / s.voxelSize;
            local.worstDistanceErrorVoxels = std::max(local.worstDistanceErrorVoxels, error);
            if (error >= 0.5) ++local.distanceFailures;
            if (expectSigned) {
                if (distance > 0.5 * s.voxelSize && (s.phi < 0.0f) != (brute.windingNumber(s.position) > 0.5))
                    ++local.signFailures;
            } else if (s.phi < 0.0f) {
                ++local.signFailures;
            }
            // The gradient: the unit vector from the closest point, signed as phi (ties excepted,
            // where either closest point's direction is exact).
            if (distance > 1e-3 * s.voxelSize) {
                const glm::dvec3 expected = (s.position - exact.point) / (s.phi < 0.0f ? -distance : distance);
                const glm::dvec3 ours(s.gradient.x(), s.gradient.y(), s.gradient.z());
                const bool unit = std::abs(glm::length(ours) - 1.0) < 1e-4;
                if (!unit || glm::length(ours - expected) > 1e-3) {
                    // A tie: another closest point as near, whose direction ours is.
                    const glm::dvec3 other = s.position - (s.phi < 0.0f ? -1.0 : 1.0) * distance * ours;
                    if (!unit || std::abs(std::sqrt(brute.closest(other).distanceSquared)) > 1e-3 * s.voxelSize)
                        ++local.gradientFailures;
                }
            }
            if (s.voxelSize != volume.voxelSize()) continue;  // far field carries no triangle
            if (s.triangle < 0) {
                ++local.missingTriangle;
                continue;
            }
            // The stored triangle's closest point is the exhaustive search's.
            const auto& t = mesh.triangles[s.triangle];
            const glm::dvec3 ours = core::closestPointOnTriangle(s.position, mesh.positions[t[0]], mesh.positions[t[1]],
                                                                 mesh.positions[t[2]])
                                        .point;
            const double pointError = glm::length(ours - exact.point) / s.voxelSize;
            const double ourDistance = glm::length(ours - s.position);
            const bool tie = std::abs(ourDistance - distance) < 1e-3 * s.voxelSize;  // equidistant points
            if (pointError > 1e-3 && !tie) ++local.pointFailures;
        }
        std::lock_guard<std::mutex> lock(mutex);
        report.distanceFailures += local.distanceFailures;
        report.signFailures += local.signFailures;
        report.pointFailures += local.pointFailures;
        report.missingTriangle += local.missingTriangle;
        report.gradientFailures += local.gradientFailures;
        report.worstDistanceErrorVoxels = std::max(report.worstDistanceErrorVoxels, local.worstDistanceErrorVoxels);
    });
    return report;
}

void expectExact(const core::TriangleMesh& mesh, const VolumeOptions& options, bool expectSigned)
{
    const SurfaceVolume volume = buildSurfaceVolume(mesh, options);
    EXPECT_EQ(volume.unsignedDistance, !expectSigned);
    const Report r = compareWithBruteForce(mesh, volume, expectSigned);
    EXPECT_GT(r.samples, 1000u);
    EXPECT_EQ(r.distanceFailures, 0u) << "worst error " << r.worstDistanceErrorVoxels << " voxels";
    EXPECT_EQ(r.signFailures, 0u);
    EXPECT_EQ(r.pointFailures, 0u);
    EXPECT_EQ(r.missingTriangle, 0u);
    EXPECT_EQ(r.gradientFailures, 0u);
    EXPECT_GE(volume.reach(), kHullOffset);
}

VolumeOptions atResolution(int resolution)
{
    VolumeOptions options;
    options.resolution = resolution;
    return options;
}

TEST(MeshToLevelSet, SphereMatchesBruteForce) { expectExact(core::makeSphere(3).mesh, atResolution(100), true); }

TEST(MeshToLevelSet, TorusMatchesBruteForce) { expectExact(core::makeTorus(48, 24).mesh, atResolution(100), true); }

TEST(MeshToLevelSet, OpenVesselTreeIsUnsignedAndExact)
{
    const core::SurfaceField tree = core::makeVesselTree(48);
    ASSERT_GT(core::boundaryEdgeCount(tree.mesh), 0u);
    expectExact(tree.mesh, atResolution(100), false);
}

TEST(MeshToLevelSet, SharedArteryMatchesBruteForce)
{
    const core::SurfaceField artery = core::loadSurface(test::sharedMesh("vampy_artery_cfd_pressure.ply"));
    expectExact(artery.mesh, atResolution(120), true);
}

TEST(MeshToLevelSet, FineBandWithCoarseFarFieldIsExact)
{
    VolumeOptions options = atResolution(320);
    options.farFieldResolution = 80;
    const core::TriangleMesh mesh = core::makeSphere(3).mesh;
    const SurfaceVolume volume = buildSurfaceVolume(mesh, options);
    ASSERT_TRUE(volume.farPhi);
    // The exterior band reaches one far voxel (4 fine ones) and two fine voxels beyond.
    EXPECT_NEAR(volume.phi->background(), 6.0 * volume.voxelSize(), 1e-6);
    const Report r = compareWithBruteForce(mesh, volume, true);
    EXPECT_EQ(r.distanceFailures, 0u) << "worst error " << r.worstDistanceErrorVoxels << " voxels";
    EXPECT_EQ(r.signFailures, 0u);
    EXPECT_EQ(r.pointFailures, 0u);
    EXPECT_EQ(r.missingTriangle, 0u);
    EXPECT_EQ(r.gradientFailures, 0u);
}

TEST(MeshToLevelSet, CappedVesselTreeIsSignedAndExact)
{
    core::SurfaceField tree = core::makeVesselTree(48);
    ASSERT_GT(core::capHoles(tree), 0u);
    EXPECT_EQ(core::boundaryEdgeCount(tree.mesh), 0u);
    expectExact(tree.mesh, atResolution(80), true);
}

TEST(MeshToLevelSet, DistanceSignOverride)
{
    VolumeOptions options = atResolution(48);
    options.sign = DistanceSign::Unsigned;
    const SurfaceVolume volume = buildSurfaceVolume(core::makeSphere(2).mesh, options);
    EXPECT_TRUE(volume.unsignedDistance);
    for (auto it = volume.phi->cbeginValueOn(); it; ++it) ASSERT_GE(*it, 0.0f);
}

TEST(MeshToLevelSet, RejectsBadOptions)
{
    const core::TriangleMesh mesh = core::makeSphere(1).mesh;
    EXPECT_THROW(buildSurfaceVolume(mesh, atResolution(8)), ValueError);
    VolumeOptions badBand = atResolution(64);
    badBand.bandVoxels = 1.0f;
    EXPECT_THROW(buildSurfaceVolume(mesh, badBand), ValueError);
    VolumeOptions badReach = atResolution(64);
    badReach.farFieldReach = std::nan("");
    EXPECT_THROW(buildSurfaceVolume(mesh, badReach), ValueError);
    EXPECT_THROW(buildSurfaceVolume(core::TriangleMesh{}, atResolution(64)), ValueError);
}

TEST(MeshToLevelSet, ResultIndependentOfThreadCount)
{
    const core::TriangleMesh mesh = core::makeTorus(32, 16).mesh;
    const SurfaceVolume many = buildSurfaceVolume(mesh, atResolution(80));
    SurfaceVolume one;
    {
        tbb::task_arena arena(1);
        arena.execute([&] { one = buildSurfaceVolume(mesh, atResolution(80)); });
    }
    ASSERT_EQ(many.phi->activeVoxelCount(), one.phi->activeVoxelCount());
    auto phi = one.phi->getConstAccessor();
    auto tri = one.triangle->getConstAccessor();
    for (auto it = many.phi->cbeginValueOn(); it; ++it) {
        ASSERT_EQ(*it, phi.getValue(it.getCoord()));
        ASSERT_EQ(many.triangle->tree().getValue(it.getCoord()), tri.getValue(it.getCoord()));
    }
}

// Each pass of exact closest points hears a request to stop at every leaf: counted per 64 leaves
// of each range TBB hands out (ranges of a few leaves), a Ctrl-C went unheard for whole passes and
// the volume was built and cached anyway.
TEST(MeshToLevelSet, EveryPassStopsWhenAskedWithinALeaf)
{
    /// Asks to stop at the first poll of the pass named @a stage, and counts the polls after it.
    class StopIn : public core::Interrupter {
    public:
        explicit StopIn(std::string stage) : mStage(std::move(stage)) {}
        void start(const char* name) override { mIn = name != nullptr && std::string(name).rfind(mStage, 0) == 0; }
        bool wasInterrupted(int) override
        {
            if (!mIn) return false;
            ++polls;
            return true;
        }
        std::atomic<int> polls{0};

    private:
        std::string mStage;
        std::atomic<bool> mIn{false};
    };
    VolumeOptions options = atResolution(320);
    options.farFieldResolution = 80;
    const core::TriangleMesh mesh = core::makeSphere(3).mesh;
    for (const char* stage : {"closest points", "far field"}) {
        StopIn stop(stage);
        EXPECT_THROW(buildSurfaceVolume(mesh, options, &stop), Cancelled) << stage;
        // Each thread stops at its next leaf: a few polls, not one per leaf of the pass.
        EXPECT_GE(stop.polls.load(), 1) << stage;
        EXPECT_LE(stop.polls.load(), 64) << stage;
    }
}

}  // namespace
}  // namespace ivis::vdb
