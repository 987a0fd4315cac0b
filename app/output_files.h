/// @file output_files.h
/// @brief The checks a command makes of the files it will write, before it reads anything: so a
///        mistyped name fails at once and leaves nothing behind.
#pragma once

#include <string>
#include <vector>

namespace ivis::app {

/// @brief A file a command writes: its path (empty: not asked for), the option that names it and
///        the extensions its format takes (empty: any, as for JSON and Markdown).
struct OutputFile {
    std::string path;
    std::string option;
    std::vector<std::string> extensions;
};

/// @brief Checks, before any work, that the folder of output file @a path exists (outputs never
///        create folders, so a mistyped -o leaves nothing behind).
/// @throw InputError "<path>: cannot write (folder '<folder>' does not exist)"
void checkOutputFolder(const std::string& path);

/// @brief Checks each of @a outputs that is asked for: its folder exists, it is not a folder, its name ends in one of
///        its extensions (in any case: -o writes PNG, so "x.jpg" would be a PNG misnamed), and no two
///        name the same file (one would overwrite the other).
/// @throw InputError naming the file and the problem
void checkOutputFiles(const std::vector<OutputFile>& outputs);

}  // namespace ivis::app
