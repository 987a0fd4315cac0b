#include "output_files.h"

#include <ivis/core/errors.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace ivis::app {

void checkOutputFolder(const std::string& path)
{
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
        throw InputError(path + ": cannot write (folder '" + folder.string() + "' does not exist)");
}

void checkOutputFiles(const std::vector<OutputFile>& outputs)
{
    std::vector<std::pair<std::filesystem::path, const OutputFile*>> seen;
    for (const OutputFile& output : outputs) {
        if (output.path.empty()) continue;
        checkOutputFolder(output.path);
        if (std::filesystem::is_directory(output.path))
            throw InputError(output.path + ": " + output.option + " names a folder, not a file");
        if (!output.extensions.empty()) {
            std::string extension = std::filesystem::path(output.path).extension().string();
            std::transform(extension.begin(), extension.end(), extension.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            if (std::find(output.extensions.begin(), output.extensions.end(), extension) == output.extensions.end()) {
                std::string names;
                for (const std::string& e : output.extensions) names += (names.empty() ? "" : " or ") + e;
                throw InputError(output.path + ": " + output.option + " writes " + names + " files (name it so)");
            }
        }
        const std::filesystem::path file = std::filesystem::weakly_canonical(std::filesystem::absolute(output.path));
        for (const auto& [other, named] : seen)
            if (other == file)
                throw InputError(output.path + ": named by both " + named->option + " and " + output.option +
                                 " (one would overwrite the other)");
        seen.emplace_back(file, &output);
    }
}

}  // namespace ivis::app
