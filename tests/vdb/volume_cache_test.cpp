// Volume cache: round trip, stale detection (other mesh, other resolution), corrupt detection.
#include "test_support.h"

#include <ivis/core/errors.h>
#include <ivis/core/file_bytes.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/vdb/cache_folder.h>
#include <ivis/vdb/volume_cache.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace ivis::vdb {
namespace {

namespace fs = std::filesystem;

VolumeOptions smallOptions()
{
    VolumeOptions options;
    options.resolution = 48;
    return options;
}

template <typename GridT>
void expectSameGrid(const GridT& a, const GridT& b)
{
    ASSERT_EQ(a.activeVoxelCount(), b.activeVoxelCount());
    auto other = b.getConstAccessor();
    for (auto it = a.cbeginValueOn(); it; ++it) {
        ASSERT_TRUE(other.isValueOn(it.getCoord()));
        ASSERT_EQ(*it, other.getValue(it.getCoord()));
    }
}

bool hasTemporaryFiles(const std::string& folder)
{
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().string().find(".tmp.") != std::string::npos) return true;
    return false;
}

TEST(VolumeCache, RoundTripKeepsEveryGrid)
{
    test::TempDir dir;
    const core::TriangleMesh mesh = core::makeSphere(2).mesh;
    VolumeOptions options = smallOptions();
    options.resolution = 96;
    options.farFieldResolution = 48;  // exercise the far-field grid too
    const SurfaceVolume built = buildSurfaceVolume(mesh, options);
    ASSERT_TRUE(built.farPhi);
    writeVolume(built, dir.file("v.vdb"));
    EXPECT_FALSE(hasTemporaryFiles(dir.path()));
    const SurfaceVolume read = readVolume(dir.file("v.vdb"));
    expectSameGrid(*built.phi, *read.phi);
    expectSameGrid(*built.triangle, *read.triangle);
    expectSameGrid(*built.gradient, *read.gradient);
    expectSameGrid(*built.farPhi, *read.farPhi);
    expectSameGrid(*built.farGradient, *read.farGradient);
    EXPECT_EQ(read.meshHash, built.meshHash);
    EXPECT_EQ(read.options.resolution, 96);
    EXPECT_EQ(read.triangle->background(), -1);
    EXPECT_EQ(read.unsignedDistance, built.unsignedDistance);
}

TEST(VolumeCache, ReusesMatchingCache)
{
    test::TempDir dir;
    const core::TriangleMesh mesh = core::makeSphere(2).mesh;
    CacheOutcome outcome{};
    loadOrBuildVolume(mesh, smallOptions(), dir.file("v.vdb"), nullptr, &outcome);
    EXPECT_EQ(outcome, CacheOutcome::Built);
    const SurfaceVolume reused = loadOrBuildVolume(mesh, smallOptions(), dir.file("v.vdb"), nullptr, &outcome);
    EXPECT_EQ(outcome, CacheOutcome::Reused);
    EXPECT_GT(reused.phi->activeVoxelCount(), 0u);
}

TEST(VolumeCache, OneGeometryReadFromTwoFilesSharesItsCache)
{
    // The steps of a series rendered one by one (a Python script's loop) each built and kept a
    // volume of the same geometry under their own names.
    test::TempDir dir;
    const core::TriangleMesh mesh = core::makeSphere(2).mesh, other = core::makeSphere(3).mesh;
    const std::string first = defaultVolumePath(dir.path(), "steps/a_t0200.vtp", mesh, smallOptions());
    EXPECT_EQ(fs::path(first).filename().string().rfind("a_t0200.", 0), 0u) << first;
    loadOrBuildVolume(mesh, smallOptions(), first);
    const std::string second = defaultVolumePath(dir.path(), "steps/a_t0400.vtp", mesh, smallOptions());
    EXPECT_EQ(second, first);
    CacheOutcome outcome{};
    loadOrBuildVolume(mesh, smallOptions(), second, nullptr, &outcome);
    EXPECT_EQ(outcome, CacheOutcome::Reused);
    // Another geometry, resolution or reach does not take it; a file's own cache comes first.
    EXPECT_NE(defaultVolumePath(dir.path(), "steps/a_t0400.vtp", other, smallOptions()), first);
    VolumeOptions finer = smallOptions();
    finer.resolution = 64;
    EXPECT_NE(defaultVolumePath(dir.path(), "steps/a_t0400.vtp", mesh, finer), first);
    VolumeOptions nearer = smallOptions();
    nearer.farFieldReach = 1.0;
    EXPECT_NE(defaultVolumePath(dir.path(), "steps/a_t0400.vtp", mesh, nearer), first);
    const std::string own = dir.file(fs::path(first).filename().string().replace(0, 7, "b_t0600"));
    test::writeFile(own, "x");
    EXPECT_EQ(defaultVolumePath(dir.path(), "b_t0600.ply", mesh, smallOptions()), own);
}

TEST(VolumeCache, OtherMeshOrResolutionIsStale)
{
    test::TempDir dir;
    const std::string path = dir.file("v.vdb");
    CacheOutcome outcome{};
    std::string reason;
    loadOrBuildVolume(core::makeSphere(2).mesh, smallOptions(), path, nullptr, &outcome);
    loadOrBuildVolume(core::makeTorus(24, 12).mesh, smallOptions(), path, nullptr, &outcome, &reason);
    EXPECT_EQ(outcome, CacheOutcome::RebuiltStale);
    EXPECT_NE(reason.find("another mesh"), std::string::npos) << reason;
    VolumeOptions finer = smallOptions();
    finer.resolution = 64;
    const SurfaceVolume rebuilt =
        loadOrBuildVolume(core::makeTorus(24, 12).mesh, finer, path, nullptr, &outcome, &reason);
    EXPECT_EQ(outcome, CacheOutcome::RebuiltStale);
    EXPECT_NE(reason.find("resolution 48"), std::string::npos) << reason;
    EXPECT_EQ(readVolume(path).options.resolution, 64);
    EXPECT_EQ(rebuilt.options.resolution, 64);
}

TEST(VolumeCache, TruncatedFileIsDetectedAndRebuilt)
{
    test::TempDir dir;
    const std::string path = dir.file("v.vdb");
    const core::TriangleMesh mesh = core::makeSphere(2).mesh;
    writeVolume(buildSurfaceVolume(mesh, smallOptions()), path);
    fs::resize_file(path, fs::file_size(path) / 2);
    EXPECT_THROW(readVolume(path), InputError);
    CacheOutcome outcome{};
    std::string reason;
    loadOrBuildVolume(mesh, smallOptions(), path, nullptr, &outcome, &reason);
    EXPECT_EQ(outcome, CacheOutcome::RebuiltCorrupt);
    // Told by the checksum, before OpenVDB reads a byte (it said "Cannot read grid. Grid type is not registered.").
    EXPECT_NE(reason.find("no content checksum"), std::string::npos) << reason;
    EXPECT_NO_THROW(readVolume(path));
}

TEST(VolumeCache, FlippedBytesAreDetected)
{
    test::TempDir dir;
    const std::string path = dir.file("v.vdb");
    writeVolume(buildSurfaceVolume(core::makeSphere(2).mesh, smallOptions()), path);
    const auto size = fs::file_size(path);
    {
        std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
        for (std::uintmax_t offset = size * 3 / 4; offset < size * 3 / 4 + 64; ++offset) {
            file.seekp(std::streamoff(offset));
            file.put(char(0x5a));
        }
    }
    EXPECT_THROW(readVolume(path), InputError);
}

TEST(VolumeCache, ForeignFileIsRejectedWithItsName)
{
    test::TempDir dir;
    const std::string path = dir.file("notes.vdb");
    test::writeFile(path, "this is not a volume\n");
    try {
        readVolume(path);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    }
}

}  // namespace
}  // namespace ivis::vdb

namespace ivis::vdb {
namespace {

// The content checksum rejects a damaged file before OpenVDB parses it: anywhere in the file (the
// header included, where OpenVDB would otherwise read garbage counts), and a file without it.
TEST(VolumeCache, ContentChecksumRejectsDamageBeforeOpenVdbReads)
{
    test::TempDir dir;
    const std::string path = dir.file("v.vdb");
    writeVolume(buildSurfaceVolume(core::makeSphere(1).mesh, smallOptions()), path);
    const std::string bytes = core::detail::readFileBytes(path);
    auto expectRejected = [&](const std::string& damaged, const std::string& problem) {
        test::writeFile(path, damaged);
        try {
            readVolume(path);
            FAIL() << "no exception for " << problem;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
        }
    };
    for (const std::size_t offset : {std::size_t(10), std::size_t(200), bytes.size() / 2}) {
        std::string damaged = bytes;
        damaged[offset] = char(damaged[offset] ^ 0x40);
        expectRejected(damaged, "content checksum mismatch");
    }
    expectRejected(bytes.substr(0, bytes.size() - 24), "no content checksum");
    expectRejected(bytes.substr(0, bytes.size() / 3), "no content checksum");
    test::writeFile(path, bytes);
    EXPECT_NO_THROW(readVolume(path));
}

}  // namespace
}  // namespace ivis::vdb
