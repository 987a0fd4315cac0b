// Where volumes are cached and how their files are named: one place for every program (the
// command line, the viewer, the Python module).
#include <ivis/vdb/cache_folder.h>

#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/log.h>
#include <ivis/core/surface_source.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>

#include <unistd.h>

namespace ivis::vdb {

std::string cacheFolder(const std::string& cacheDir, bool create)
{
    namespace fs = std::filesystem;
    fs::path folder = ".";
    if (!cacheDir.empty()) folder = cacheDir;
    else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) folder = fs::path(xdg) / "inversevis";
    else if (const char* home = std::getenv("HOME"); home && *home) folder = fs::path(home) / ".cache" / "inversevis";
    if (!create) {
        if (!cacheDir.empty() && !fs::is_directory(folder))
            throw InputError(folder.string() + ": --cache-dir names no folder");
        return folder.string();
    }
    std::error_code error;
    fs::create_directories(folder, error);
    if (error || !fs::is_directory(folder))
        throw InputError("cache folder " + folder.string() + " cannot be created (" +
                         (error ? error.message() : std::string("not a folder")) + ")");
    return folder.string();
}

std::string writableCacheFolder(const std::string& cacheDir)
{
    const std::string folder = cacheFolder(cacheDir);
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError("cache folder " + folder + " cannot be written (" + std::strerror(errno) + ")");
    return folder;
}

std::string optionalCacheFolder(const std::string& cacheDir)
{
    try {
        return writableCacheFolder(cacheDir);
    } catch (const InputError& e) {
        core::logWarning(std::string(e.what()) +
                         ": the volume is built for this run and not kept (--cache-dir or XDG_CACHE_HOME chooses another folder)");
        return "";
    }
}

std::string defaultVolumePath(const std::string& folder, const std::string& source, const core::TriangleMesh& mesh,
                              const VolumeOptions& options)
{
    if (folder.empty()) return "";
    char reach[32], band[32] = "";
    std::snprintf(reach, sizeof reach, ".reach%g", options.farFieldReach);
    if (options.bandVoxels != VolumeOptions().bandVoxels) std::snprintf(band, sizeof band, ".band%g", options.bandVoxels);
    const char* sign = options.sign == DistanceSign::Signed     ? ".signed"
                       : options.sign == DistanceSign::Unsigned ? ".unsigned"
                                                                     : "";
    namespace fs = std::filesystem;
    const std::string suffix = "." + core::toHex(core::meshHash(mesh)) + ".res" + std::to_string(options.resolution) +
                               reach + band + sign + ".vdb";
    const fs::path own = fs::path(folder) / (core::sourceStem(source) + suffix);
    std::error_code error;
    if (fs::exists(own, error)) return own.string();
    // The same geometry cached under another file's name (the other steps of a time series, a file
    // converted or copied): its volume is this mesh's (the file's key is checked when it is read).
    std::string other;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
            (other.empty() || it->path().string() < other))
            other = it->path().string();
    }
    return other.empty() ? own.string() : other;
}

bool isVolumeCacheName(const std::string& fileName)
{
    // The reach is optional, as the hash is: the names before 2026-11-27 had no reach, and those
    // before 2026-11-24 no hash.
    static const std::regex name(R"(.+(\.[0-9a-f]{16})?\.res[0-9]+(\.reach[0-9.e+-]+)?(\.band[0-9.e+-]+)?)"
                                 R"((\.signed|\.unsigned)?\.vdb(\.tmp\.[0-9]+\.[0-9]+)?)");
    return std::regex_match(fileName, name);
}

}  // namespace ivis::vdb
