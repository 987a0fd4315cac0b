#include <ivis/vdb/volume_cache.h>

#include <ivis/core/atomic_file.h>
#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/log.h>

#include <openvdb/io/File.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

namespace ivis::vdb {
namespace {

namespace fs = std::filesystem;

constexpr const char* kVersionKey = "ivis_format_version";
constexpr const char* kMeshHashKey = "ivis_mesh_hash";
constexpr const char* kResolutionKey = "ivis_resolution";
constexpr const char* kBandKey = "ivis_band_voxels";
constexpr const char* kReachKey = "ivis_far_field_reach";
constexpr const char* kFarResolutionKey = "ivis_far_field_resolution";
constexpr const char* kUnsignedKey = "ivis_unsigned_distance";
constexpr const char* kTrianglesKey = "ivis_triangles";
constexpr const char* kChecksumKey = "ivis_checksum";

// The file is OpenVDB's bytes followed by a trailer: kTrailerMagic, the payload's length and its
// content hash (little-endian u64 each). readVolume checks it before OpenVDB parses a byte, so a
// corrupt or truncated cache never reaches OpenVDB's reader (which is not hardened: it leaks or
// crashes on some corrupt files, found by volume_cache_fuzzer).
constexpr char kTrailerMagic[8] = {'I', 'V', 'I', 'S', 'S', 'U', 'M', '4'};
constexpr std::size_t kTrailerBytes = 24;

/// Content hash of the first @a length bytes of @a in (from its start); false when it ends sooner.
bool hashPrefix(std::istream& in, std::uint64_t length, std::uint64_t& hash)
{
    core::ContentHash content;
    std::vector<char> chunk(std::size_t(1) << 20);
    in.seekg(0);
    for (std::uint64_t left = length; left > 0;) {
        const std::size_t size = std::size_t(std::min<std::uint64_t>(left, chunk.size()));
        if (!in.read(chunk.data(), std::streamsize(size))) return false;
        content.add(chunk.data(), size);
        left -= size;
    }
    hash = content.value();
    return true;
}

/// Appends the trailer to the OpenVDB file at @a path.
void appendTrailer(const std::string& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::uint64_t length = std::uint64_t(in.tellg());
    std::uint64_t hash = 0;
    if (!in || !hashPrefix(in, length, hash)) throw std::runtime_error("cannot read back the written volume");
    in.close();
    std::ofstream out(path, std::ios::binary | std::ios::app);
    out.write(kTrailerMagic, sizeof kTrailerMagic);
    for (const std::uint64_t value : {length, hash})
        for (int byte = 0; byte < 8; ++byte) out.put(char((value >> (8 * byte)) & 0xff));
    if (!out.flush()) throw std::runtime_error("cannot write the volume's checksum");
}

/// Hash of a grid's leaf origins, active masks and values: detects corrupted payloads.
template <typename GridT>
void hashGrid(const GridT& grid, core::ContentHash& hash)
{
    hash.add(grid.getName().data(), grid.getName().size());
    hash.addValue(grid.background());
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
        hash.addValue(leaf->origin());
        hash.add(&leaf->getValueMask(), sizeof(leaf->getValueMask()));
        hash.add(leaf->buffer().data(), sizeof(typename GridT::ValueType) * GridT::TreeType::LeafNodeType::SIZE);
    }
}

std::string checksum(const SurfaceVolume& volume)
{
    core::ContentHash hash;
    hashGrid(*volume.phi, hash);
    hashGrid(*volume.triangle, hash);
    hashGrid(*volume.gradient, hash);
    if (volume.farPhi) hashGrid(*volume.farPhi, hash);
    if (volume.farGradient) hashGrid(*volume.farGradient, hash);
    return hash.hex();
}

/// The options/mesh facts a cache file was written for.
struct CacheKey {
    int version = 0;
    std::string meshHash;
    int resolution = 0;
    float bandVoxels = 0.0f;
    double reach = 0.0;
    int farResolution = 0;
    bool unsignedDistance = false;
    std::int64_t triangles = 0;
    std::string checksum;
};

CacheKey readKey(const openvdb::MetaMap& meta, const std::string& path)
{
    try {
        CacheKey key;
        key.version = meta.metaValue<openvdb::Int32>(kVersionKey);
        key.meshHash = meta.metaValue<std::string>(kMeshHashKey);
        key.resolution = meta.metaValue<openvdb::Int32>(kResolutionKey);
        key.bandVoxels = meta.metaValue<float>(kBandKey);
        key.reach = meta.metaValue<double>(kReachKey);
        key.farResolution = meta.metaValue<openvdb::Int32>(kFarResolutionKey);
        key.unsignedDistance = meta.metaValue<bool>(kUnsignedKey);
        key.triangles = meta.metaValue<openvdb::Int64>(kTrianglesKey);
        key.checksum = meta.metaValue<std::string>(kChecksumKey);
        return key;
    } catch (const openvdb::Exception&) {
        throw InputError(path + ": not an inversevis volume (metadata missing)");
    }
}

/// Opens a volume file and reads only its metadata.
CacheKey readCacheKey(const std::string& path)
{
    detail::initializeOpenVdb();
    try {
        openvdb::io::File file(path);
        file.open(/*delayLoad=*/false);
        CacheKey key = readKey(*file.getMetadata(), path);
        file.close();
        return key;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": corrupt or truncated volume file (" + oneLine(e.what()) + ")");
    }
}

/// Why a cache written with @a key does not fit the request ("" when it fits).
std::string staleReason(const CacheKey& key, const core::TriangleMesh& mesh, const VolumeOptions& options)
{
    if (key.version != kVolumeFormatVersion)
        return "format version " + std::to_string(key.version) + ", expected " + std::to_string(kVolumeFormatVersion);
    if (key.meshHash != core::toHex(core::meshHash(mesh))) return "built from another mesh";
    if (key.resolution != options.resolution)
        return "resolution " + std::to_string(key.resolution) + ", requested " + std::to_string(options.resolution);
    if (key.bandVoxels != options.bandVoxels) return "another band width";
    if (key.reach != options.farFieldReach || key.farResolution != options.farFieldResolution)
        return "another far field";
    if (key.unsignedDistance != usesUnsignedDistance(mesh, options.sign)) return "another distance sign mode";
    return "";
}

template <typename GridT>
typename GridT::Ptr findGrid(const openvdb::GridPtrVecPtr& grids, const std::string& name, const std::string& path)
{
    for (const auto& base : *grids)
        if (base->getName() == name)
            if (auto grid = openvdb::gridPtrCast<GridT>(base)) return grid;
    throw InputError(path + ": grid '" + name + "' missing or of the wrong type");
}

/// The grids named @a names of the OpenVDB file at @a path, each read and decompressed by a file
/// handle of its own, in parallel (a volume is a few large grids).
openvdb::GridPtrVecPtr readGridsInParallel(const std::string& path, const std::vector<std::string>& names)
{
    auto grids = std::make_shared<openvdb::GridPtrVec>(names.size());
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, names.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                openvdb::io::File own(path);
                own.open(/*delayLoad=*/false);
                (*grids)[i] = own.readGrid(names[i]);
                own.close();
            }
        },
        tbb::simple_partitioner());
    return grids;
}

}  // namespace

const char* toString(CacheOutcome outcome)
{
    switch (outcome) {
    case CacheOutcome::Built: return "built";
    case CacheOutcome::Reused: return "reused";
    case CacheOutcome::RebuiltStale: return "rebuilt-stale";
    case CacheOutcome::RebuiltCorrupt: return "rebuilt-corrupt";
    }
    return "unknown";
}

void writeVolume(const SurfaceVolume& volume, const std::string& path)
{
    detail::initializeOpenVdb();
    IVIS_CHECK(volume.phi && volume.triangle && volume.gradient);
    IVIS_CHECK(bool(volume.farPhi) == bool(volume.farGradient));
    openvdb::MetaMap meta;
    meta.insertMeta(kVersionKey, openvdb::Int32Metadata(kVolumeFormatVersion));
    meta.insertMeta(kMeshHashKey, openvdb::StringMetadata(core::toHex(volume.meshHash)));
    meta.insertMeta(kResolutionKey, openvdb::Int32Metadata(volume.options.resolution));
    meta.insertMeta(kBandKey, openvdb::FloatMetadata(volume.options.bandVoxels));
    meta.insertMeta(kReachKey, openvdb::DoubleMetadata(volume.options.farFieldReach));
    meta.insertMeta(kFarResolutionKey, openvdb::Int32Metadata(volume.options.farFieldResolution));
    meta.insertMeta(kUnsignedKey, openvdb::BoolMetadata(volume.unsignedDistance));
    meta.insertMeta(kTrianglesKey, openvdb::Int64Metadata(openvdb::Int64(volume.triangleCount)));
    meta.insertMeta(kChecksumKey, openvdb::StringMetadata(checksum(volume)));

    openvdb::GridCPtrVec grids{volume.phi, volume.triangle, volume.gradient};
    if (volume.farPhi) grids.insert(grids.end(), {volume.farPhi, volume.farGradient});

    const fs::path target(path);
    if (target.has_parent_path()) {
        std::error_code error;
        fs::create_directories(target.parent_path(), error);
    }
    core::writeAtomically(path, [&](const std::string& temporary) {
        openvdb::io::File file(temporary);
        file.write(grids, meta);
        file.close();
        appendTrailer(temporary);
    });
}

void checkVolumeChecksum(const std::string& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::uint64_t size = in ? std::uint64_t(in.tellg()) : 0;
    char trailer[kTrailerBytes] = {};
    if (!in || size < kTrailerBytes || !in.seekg(std::streamoff(size - kTrailerBytes)) ||
        !in.read(trailer, kTrailerBytes) || !std::equal(kTrailerMagic, kTrailerMagic + 8, trailer))
        throw InputError(path + ": not an inversevis volume of format " + std::to_string(kVolumeFormatVersion) +
                         " (no content checksum: an older cache, another file, or a truncated one)");
    auto u64 = [&](int at) {
        std::uint64_t value = 0;
        for (int byte = 7; byte >= 0; --byte) value = (value << 8) | std::uint8_t(trailer[at + byte]);
        return value;
    };
    std::uint64_t hash = 0;
    if (u64(8) != size - kTrailerBytes || !hashPrefix(in, u64(8), hash) || hash != u64(16))
        throw InputError(path + ": corrupt or truncated volume file (content checksum mismatch)");
}

namespace {

/// readVolume once the file's checksum has been checked.
SurfaceVolume readCheckedVolume(const std::string& path)
{
    SurfaceVolume volume;
    CacheKey key;
    try {
        openvdb::io::File file(path);
        file.open(/*delayLoad=*/false);
        key = readKey(*file.getMetadata(), path);
        std::vector<std::string> names;
        for (auto name = file.beginName(); name != file.endName(); ++name) names.push_back(name.gridName());
        file.close();
        const openvdb::GridPtrVecPtr grids = readGridsInParallel(path, names);
        volume.phi = findGrid<openvdb::FloatGrid>(grids, "phi", path);
        volume.triangle = findGrid<openvdb::Int32Grid>(grids, "triangle", path);
        volume.gradient = findGrid<openvdb::Vec3SGrid>(grids, "gradient", path);
        for (const auto& base : *grids)
            if (base->getName() == "far_phi") {
                volume.farPhi = findGrid<openvdb::FloatGrid>(grids, "far_phi", path);
                volume.farGradient = findGrid<openvdb::Vec3SGrid>(grids, "far_gradient", path);
            }
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": corrupt or truncated volume file (" + oneLine(e.what()) + ")");
    }
    if (key.version != kVolumeFormatVersion)
        throw InputError(path + ": volume format version " + std::to_string(key.version) + ", expected " +
                         std::to_string(kVolumeFormatVersion));
    if (checksum(volume) != key.checksum) throw InputError(path + ": corrupt volume file (checksum mismatch)");
    const bool sameTopology = volume.phi->tree().hasSameTopology(volume.triangle->tree()) &&
                              volume.phi->tree().hasSameTopology(volume.gradient->tree()) &&
                              (!volume.farPhi || volume.farPhi->tree().hasSameTopology(volume.farGradient->tree()));
    if (!sameTopology) throw InputError(path + ": corrupt volume file (grids of different extent)");
    volume.options.resolution = key.resolution;
    volume.options.bandVoxels = key.bandVoxels;
    volume.options.farFieldReach = key.reach;
    volume.options.farFieldResolution = key.farResolution;
    volume.options.sign = key.unsignedDistance ? DistanceSign::Unsigned : DistanceSign::Signed;
    volume.unsignedDistance = key.unsignedDistance;
    volume.meshHash = std::stoull(key.meshHash, nullptr, 16);
    volume.triangleCount = std::size_t(key.triangles);
    return volume;
}

}  // namespace

SurfaceVolume readVolume(const std::string& path)
{
    detail::initializeOpenVdb();
    if (!fs::exists(path)) throw InputError(path + ": file not found");
    checkVolumeChecksum(path);
    return readCheckedVolume(path);
}

SurfaceVolume loadOrBuildVolume(const core::TriangleMesh& mesh, const VolumeOptions& options,
                                const std::string& path, core::Interrupter* interrupter,
                                CacheOutcome* outcome, std::string* reason)
{
    validate(options);
    CacheOutcome result = CacheOutcome::Built;
    std::string why;
    if (fs::exists(path)) {
        try {
            // The checksum first: a truncated or damaged file never reaches OpenVDB's reader.
            checkVolumeChecksum(path);
            why = staleReason(readCacheKey(path), mesh, options);
            if (why.empty()) {
                SurfaceVolume cached = readCheckedVolume(path);
                if (outcome) *outcome = CacheOutcome::Reused;
                if (reason) reason->clear();
                return cached;
            }
            result = CacheOutcome::RebuiltStale;
            core::logInfo(path + ": stale volume cache (" + why + "), rebuilding");
        } catch (const InputError& e) {
            result = CacheOutcome::RebuiltCorrupt;
            why = e.what();
            core::logWarning(why + "; rebuilding");
        }
    }
    SurfaceVolume volume = buildSurfaceVolume(mesh, options, interrupter);
    if (!path.empty()) writeVolume(volume, path);
    if (outcome) *outcome = result;
    if (reason) *reason = why;
    return volume;
}

}  // namespace ivis::vdb
