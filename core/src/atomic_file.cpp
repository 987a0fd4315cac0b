#include <ivis/core/atomic_file.h>

#include <ivis/core/errors.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

namespace ivis::core {

namespace {

/// A fresh temporary name beside @a path: "<path>.tmp.<pid>.<n>", its file name cut so that the
/// whole stays within the 255 bytes a file name may have (a name near that limit is still written).
std::string temporaryFor(const std::string& path)
{
    static std::atomic<int> counter{0};
    constexpr std::size_t kNameMax = 255;
    const std::string suffix = ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    const std::filesystem::path target(path);
    std::string name = target.filename().string();
    if (name.size() + suffix.size() > kNameMax) name.resize(kNameMax - suffix.size());
    return (target.parent_path() / (name + suffix)).string();
}

/// Whether @a path names an open descriptor: /dev/stdout, /dev/stderr, /dev/stdin, /dev/fd/N or
/// /proc/self/fd/N.
bool namesDescriptor(const std::string& path)
{
    const std::string lexical = std::filesystem::path(path).lexically_normal().string();
    return lexical == "/dev/stdout" || lexical == "/dev/stderr" || lexical == "/dev/stdin" ||
           lexical.rfind("/dev/fd/", 0) == 0 || lexical.rfind("/proc/self/fd/", 0) == 0;
}

/// The program's own stream that @a path names (standard output or error), or null.
std::ostream* standardStream(const std::string& path)
{
    const std::string lexical = std::filesystem::path(path).lexically_normal().string();
    if (lexical == "/dev/stdout" || lexical == "/dev/fd/1" || lexical == "/proc/self/fd/1") return &std::cout;
    if (lexical == "/dev/stderr" || lexical == "/dev/fd/2" || lexical == "/proc/self/fd/2") return &std::cerr;
    return nullptr;
}

/// Calls @a write with @a temporary, then appends what it wrote to @a stream and removes it.
void writeThrough(const std::string& temporary, std::ostream& stream, const std::function<void(const std::string&)>& write)
{
    struct Removal {
        const std::string& path;
        ~Removal()
        {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    } removal{temporary};
    write(temporary);
    std::ifstream in(temporary, std::ios::binary);
    if (!in) throw std::runtime_error("its content was not written");
    stream << in.rdbuf();
    stream.flush();
    if (!stream) throw std::runtime_error("the stream refused it");
}

/// Calls @a write with @a path itself (a stream: isStream), or, for the program's standard output
/// or error, with a temporary file whose bytes then go there; a failure names @a path.
void writeStream(const std::string& path, const std::function<void(const std::string&)>& write)
{
    try {
        if (std::ostream* stream = standardStream(path)) {  // temporaryFor names it by the process and a count
            writeThrough(temporaryFor((std::filesystem::temp_directory_path() / "inversevis-stream").string()), *stream,
                         write);
        } else {
            write(path);
        }
    } catch (const Cancelled&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot write (" + oneLine(e.what()) + ")");
    }
}

/// Calls @a write with @a temporary; on failure removes it and rethrows (naming @a path).
void writeTemporary(const std::string& temporary, const std::string& path,
                    const std::function<void(const std::string&)>& write, bool rename)
{
    try {
        write(temporary);
        if (rename) {
            std::error_code error;
            std::filesystem::rename(temporary, path, error);
            if (error) throw std::runtime_error(error.message());
        }
    } catch (const Cancelled&) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        const std::string why = e.what();
        // An InputError from the writer already names a path: keep only its reason, and only once
        // when the writer wrote atomically itself ("<temporary>: cannot write (<why>)").
        const std::size_t colon = why.rfind(": ");
        std::string reason = colon == std::string::npos ? why : why.substr(colon + 2);
        const std::string nested = "cannot write (";
        if (reason.rfind(nested, 0) == 0 && reason.back() == ')')
            reason = reason.substr(nested.size(), reason.size() - nested.size() - 1);
        throw InputError(path + ": cannot write (" + reason + ")");
    }
}

}  // namespace

bool isStream(const std::string& path)
{
    if (namesDescriptor(path)) return true;
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
           !std::filesystem::is_directory(status);
}

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
    if (isStream(path)) return writeStream(path, write);
    writeTemporary(temporaryFor(path), path, write, /*rename=*/true);
}

AtomicFileSet::~AtomicFileSet()
{
    for (const auto& [temporary, path] : mFiles) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
    }
}

void AtomicFileSet::write(const std::string& path, const std::function<void(const std::string&)>& write)
{
    if (isStream(path)) return writeStream(path, write);  // now: a stream cannot wait for the set
    const std::string temporary = temporaryFor(path);
    writeTemporary(temporary, path, write, /*rename=*/false);
    mFiles.emplace_back(temporary, path);
}

void AtomicFileSet::commit()
{
    for (const auto& [temporary, path] : mFiles) {
        std::error_code error;
        std::filesystem::rename(temporary, path, error);
        if (error) throw InputError(path + ": cannot write (" + error.message() + ")");
    }
    mFiles.clear();
}

}  // namespace ivis::core
