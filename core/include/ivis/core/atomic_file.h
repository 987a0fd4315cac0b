/// @file atomic_file.h
/// @brief Writes an output through a temporary file in the same folder and renames it into place,
///        so that a reader never sees a partial file.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ivis::core {

/// @brief Whether @a path is a device, FIFO or socket (/dev/null, a named pipe) or names an open
///        descriptor (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, whatever it is
///        redirected to): such a target is written to as it is, since renaming a file over it would
///        replace it. What is written to the program's own standard output or error follows what
///        it printed there before (a file it is redirected to is not truncated).
bool isStream(const std::string& path);

/// @brief Calls @a write with a temporary path beside @a path, then renames it to @a path.
///        On any failure the temporary is removed and InputError "<path>: cannot write (<why>)" is
///        thrown; an existing file at @a path is left untouched. A device, FIFO or socket at
///        @a path (/dev/stdout, a named pipe) is written to directly instead, never replaced.
/// @param write writes the complete content to the path it is given; throws on failure
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

/// @brief Outputs written under temporary names and renamed into place together once all are
///        written, so that a failure while writing a set of files (the frames of a series) leaves
///        none of them; each file appears whole.
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;
    /// @brief Removes the temporaries of a set that was not committed.
    ~AtomicFileSet();

    /// @brief Calls @a write with a temporary path beside @a path; commit() renames it to @a path
    ///        (a device, FIFO or socket at @a path is written to directly, at once).
    /// @throw InputError "<path>: cannot write (<why>)" when @a write fails (its temporary removed)
    void write(const std::string& path, const std::function<void(const std::string&)>& write);
    /// @brief Renames every temporary into place, in the order written.
    /// @throw InputError "<path>: cannot write (<why>)" when a rename fails (the files renamed before
    ///        it stay in place, each whole; the later temporaries are removed)
    void commit();

private:
    std::vector<std::pair<std::string, std::string>> mFiles;  ///< (temporary, path)
};

}  // namespace ivis::core
