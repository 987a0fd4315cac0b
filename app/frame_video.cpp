#include "frame_video.h"

#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace ivis::app {
namespace {

namespace fs = std::filesystem;

/// @a fps as ffmpeg's -framerate reads it: "7", "2.5", "0.333333".
std::string frameRateText(double fps)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", fps);
    return text;
}

/// @a path with "_" and @a number inserted before its extension.
std::string withSuffix(const std::string& path, const std::string& number)
{
    const fs::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + number + p.extension().string())).string();
}

/// The frames of @a path as ffmpeg's image-sequence pattern ("out_%04d.png"; a '%' of the path doubled).
std::string framePattern(const std::string& path, std::size_t count)
{
    std::string escaped;
    for (const char c : path) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return withSuffix(escaped, "%0" + std::to_string(frameDigits(count)) + "d");
}

/// Runs @a arguments (the program first) with stdout discarded and stderr into @a errorLog.
/// @return the exit status (-1 when it could not be started or did not exit)
int runProgram(const std::vector<std::string>& arguments, const std::string& errorLog)
{
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, errorLog.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return -1;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The last non-empty line of the file @a path ("" when there is none).
std::string lastLine(const std::string& path)
{
    std::ifstream in(path);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

}  // namespace

int frameDigits(std::size_t count)
{
    int digits = 1;
    for (std::size_t last = count > 0 ? count - 1 : 0; last >= 10; last /= 10) ++digits;
    return std::max(4, digits);
}

std::string framePath(const std::string& path, std::size_t index, std::size_t count)
{
    std::string number = std::to_string(index);
    number.insert(0, std::size_t(std::max(0, frameDigits(count) - int(number.size()))), '0');
    return withSuffix(path, number);
}

std::string videoPath(const std::string& path) { return fs::path(path).replace_extension(".mp4").string(); }

std::optional<std::string> findFfmpeg()
{
    const char* path = std::getenv("PATH");
    if (path == nullptr) return std::nullopt;
    const std::string folders = path;
    for (std::size_t start = 0; start <= folders.size();) {
        const std::size_t end = std::min(folders.find(':', start), folders.size());
        const fs::path candidate = fs::path(folders.substr(start, end - start)) / "ffmpeg";
        std::error_code ec;
        if (end > start && fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
            return candidate.string();
        start = end + 1;
    }
    return std::nullopt;
}

std::string writeVideo(const std::string& ffmpeg, const std::string& path, std::size_t count, double fps,
                       const std::string& video)
{
    std::string failure;
    try {
        core::writeAtomically(video, [&](const std::string& temporary) {
            const std::string errorLog = temporary + ".log";
            const int status = runProgram({ffmpeg, "-nostdin", "-y", "-loglevel", "error", "-framerate",
                                           frameRateText(fps), "-i", framePattern(path, count),
                                           // only this series' frames, whatever an older, longer one left
                                           "-frames:v", std::to_string(count), "-vf",
                                           "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-f", "mp4",
                                           temporary},
                                          errorLog);
            const std::string why = lastLine(errorLog);
            std::error_code ignored;
            fs::remove(errorLog, ignored);
            if (status != 0) {
                failure = (status < 0 ? "ffmpeg did not run to its end" : "ffmpeg exited with status " +
                                                                               std::to_string(status)) +
                          (why.empty() ? "" : ": " + why);
                throw std::runtime_error(failure);
            }
        });
    } catch (const InputError& e) {
        return failure.empty() ? e.what() : failure;
    }
    return "";
}

}  // namespace ivis::app
