// `inversevis cache list|clear`: the volume caches in the cache folder shared by every command and
// the viewer.
#include "cli_checks.h"
#include "commands.h"
#include "mesh_options.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/errors.h>
#include <ivis/core/log.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <signal.h>
#include <sys/types.h>

namespace ivis::app {
namespace {

namespace fs = std::filesystem;

struct CacheEntry {
    fs::path path;
    std::uintmax_t bytes = 0;
};

/// The volume caches of @a folder and the temporaries an interrupted write left, by name: only
/// files named as this program names them (isVolumeCacheName), never another .vdb (none when
/// the folder does not exist yet).
std::vector<CacheEntry> cacheEntries(const std::string& folder)
{
    std::vector<CacheEntry> entries;
    if (!fs::exists(folder)) return entries;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
        if (!entry.is_regular_file() || !vdb::isVolumeCacheName(entry.path().filename().string())) continue;
        entries.push_back({entry.path(), entry.file_size()});
    }
    if (error) throw InputError(folder + ": cannot list the cache folder (" + error.message() + ")");
    std::sort(entries.begin(), entries.end(), [](const CacheEntry& a, const CacheEntry& b) { return a.path < b.path; });
    return entries;
}

/// True for a temporary ("<volume>.tmp.<pid>.<n>") whose writer still runs on this machine: a
/// command building that volume now (removing it made that command fail).
bool isBeingWritten(const fs::path& path)
{
    const std::string name = path.filename().string();
    const std::size_t tmp = name.rfind(".tmp.");
    if (tmp == std::string::npos) return false;
    const long pid = std::strtol(name.c_str() + tmp + 5, nullptr, 10);
    return pid > 0 && pid <= std::numeric_limits<pid_t>::max() && (::kill(pid_t(pid), 0) == 0 || errno == EPERM);
}

std::string humanBytes(std::uintmax_t bytes)
{
    char text[32];
    if (bytes < 1024 * 1024) std::snprintf(text, sizeof text, "%.1f KiB", double(bytes) / 1024.0);
    else if (bytes < std::uintmax_t(1) << 30) std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1 << 20));
    else std::snprintf(text, sizeof text, "%.2f GiB", double(bytes) / double(std::uintmax_t(1) << 30));
    return text;
}

}  // namespace

Command addCacheCommand(CLI::App& app)
{
    auto cacheDir = std::make_shared<std::string>();
    CLI::App* command = app.add_subcommand("cache", "List or clear the volume caches shared by every command and the viewer");
    command->add_option("--cache-dir", *cacheDir, kCacheDirHelp)->check(nonEmpty());
    CLI::App* list = command->add_subcommand("list", "Each cached volume with its size, and the total");
    CLI::App* clear = command->add_subcommand(
        "clear", "Remove every cached volume (and leftover temporaries): the files named as this program names them");
    command->require_subcommand(1);
    list->fallthrough();  // --cache-dir may follow list / clear
    clear->fallthrough();

    return {command, [cacheDir, list, clear] {
        const std::string folder = vdb::cacheFolder(*cacheDir, false);
        const std::vector<CacheEntry> entries = cacheEntries(folder);
        if (list->parsed()) {
            std::uintmax_t total = 0;
            for (const CacheEntry& e : entries) total += e.bytes;
            for (const CacheEntry& e : entries)
                std::printf("%10s  %s\n", humanBytes(e.bytes).c_str(), e.path.filename().string().c_str());
            std::printf("%10s  in %zu file%s in %s\n", humanBytes(total).c_str(), entries.size(),
                        entries.size() == 1 ? "" : "s", folder.c_str());
        } else if (clear->parsed()) {
            std::size_t removed = 0, writing = 0;
            std::uintmax_t freed = 0;
            for (const CacheEntry& e : entries) {
                if (isBeingWritten(e.path)) {
                    ++writing;
                    continue;
                }
                std::error_code error;
                if (!fs::remove(e.path, error) && error)
                    throw InputError(e.path.string() + ": cannot remove (" + error.message() + ")");
                ++removed;
                freed += e.bytes;
            }
            core::logInfo("removed " + std::to_string(removed) + " cached volume" + (removed == 1 ? "" : "s") + " (" +
                          humanBytes(freed) + ") from " + folder +
                          (writing == 0 ? std::string()
                                        : "; kept " + std::to_string(writing) + " being written by a running command"));
        }
    }};
}

}  // namespace ivis::app
