/// @file output_files.h
/// @brief The checks a command makes of the files it will write, before it reads anything: so a
///        mistyped name fails at once and leaves nothing behind.
#pragma once

#include <string>
#include <vector>

namespace ivis::app {

/// @brief A file a command writes: its path (empty: not asked for), the option that names it and
///        the extensions its format takes (empty: any).
struct OutputFile {
    std::string path;
    std::string option;
    std::vector<std::string> extensions;
    bool stream = false;  ///< text that may go to a stream (/dev/stdout, a named pipe), whatever its name
};

/// @brief A JSON file a command writes: named .json, or a stream.
OutputFile jsonOutput(const std::string& path, const std::string& option);

/// @brief A Markdown file a command writes: named .md or .markdown, or a stream.
OutputFile markdownOutput(const std::string& path, const std::string& option);

/// @brief Checks, before any work, that the folder of output file @a path exists (outputs never
///        create folders, so a mistyped -o leaves nothing behind).
/// @throw InputError "<path>: cannot write (folder '<folder>' does not exist)"
void checkOutputFolder(const std::string& path);

/// @brief A file a command reads: its path (empty: not given) and what gives it ("the mesh", "--scalar-file").
struct InputFile {
    std::string path;
    std::string option;
};

/// @brief The files a command reads, for checkOutputFiles: its meshes (a .pvd and its steps' files),
///        --scalar-file, --camera and --view (each empty when not given or not taken).
/// @throw InputError for a .pvd that cannot be read
std::vector<InputFile> readFiles(const std::vector<std::string>& meshes, const std::string& scalarFile,
                                 const std::string& cameraFile, const std::string& viewFile);

/// @brief Checks each of @a outputs that is asked for: its folder exists, it is not a folder, its name ends in one of
///        its extensions (in any case: -o writes PNG, so "x.jpg" would be a PNG misnamed; a JSON
///        file named "fig.png" would replace a figure) unless it is a stream that may be, no two
///        name the same file (one would overwrite the other), and none names one of @a inputs.
/// @throw InputError naming the file and the problem
void checkOutputFiles(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs = {});

}  // namespace ivis::app
