#include "output_files.h"

#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>
#include <ivis/core/file_extension.h>
#include <ivis/core/pvd_reader.h>
#include <ivis/core/surface_source.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace ivis::app {

OutputFile jsonOutput(const std::string& path, const std::string& option) { return {path, option, {".json"}, true}; }

OutputFile markdownOutput(const std::string& path, const std::string& option)
{
    return {path, option, {".md", ".markdown"}, true};
}

void checkOutputFolder(const std::string& path)
{
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
        throw InputError(path + ": cannot write (folder '" + folder.string() + "' does not exist)");
}

std::vector<InputFile> readFiles(const std::vector<std::string>& meshes, const std::string& scalarFile,
                                 const std::string& cameraFile, const std::string& viewFile)
{
    std::vector<InputFile> inputs;
    for (const std::string& mesh : meshes) {
        if (mesh.rfind(core::kScenePrefix, 0) == 0) continue;
        inputs.push_back({mesh, "the mesh"});
        if (core::isTimeSeries(mesh))
            for (const core::TimeStep& step : core::readPvd(mesh)) inputs.push_back({step.path, "a step of " + mesh});
    }
    inputs.push_back({scalarFile, "--scalar-file"});
    inputs.push_back({cameraFile, "--camera"});
    inputs.push_back({viewFile, "--view"});
    return inputs;
}

void checkOutputFiles(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs)
{
    // The file a path names, symbolic links and ".." resolved where they can be (an unreadable
    // folder, a loop: the path as written, made absolute).
    auto fileOf = [](const std::string& path) {
        std::error_code error;
        const std::filesystem::path absolute = std::filesystem::absolute(path, error);
        if (error) return std::filesystem::path(path).lexically_normal();
        const std::filesystem::path file = std::filesystem::weakly_canonical(absolute, error);
        return error ? absolute.lexically_normal() : file;
    };
    // Each path resolved once, and looked up by it: a series has as many outputs and inputs as steps.
    std::map<std::filesystem::path, const InputFile*> read;
    for (const InputFile& input : inputs)
        if (!input.path.empty()) read.emplace(fileOf(input.path), &input);
    std::map<std::filesystem::path, const OutputFile*> seen;
    for (const OutputFile& output : outputs) {
        if (output.path.empty()) continue;
        checkOutputFolder(output.path);
        if (std::filesystem::is_directory(output.path))
            throw InputError(output.path + ": " + output.option + " names a folder, not a file");
        const std::filesystem::path file = fileOf(output.path);
        if (const auto named = seen.find(file); named != seen.end())
            throw InputError(output.path + ": named by both " + named->second->option + " and " + output.option +
                             " (one would overwrite the other)");
        if (const auto input = read.find(file); input != read.end())
            throw InputError(output.path + ": " + output.option + " would overwrite " + input->second->option +
                             ", which this command reads");
        seen.emplace(file, &output);
    }
    // Names are checked after: that a file is named twice, or is read, says more than its extension.
    for (const OutputFile& output : outputs) {
        if (output.path.empty() || output.extensions.empty() || (output.stream && core::isStream(output.path)))
            continue;
        const std::string extension = core::lowerCaseExtension(output.path);
        if (std::find(output.extensions.begin(), output.extensions.end(), extension) == output.extensions.end()) {
            std::string names;
            for (const std::string& e : output.extensions) names += (names.empty() ? "" : " or ") + e;
            throw InputError(output.path + ": " + output.option + " writes " + names + " files (name it so)");
        }
    }
}

}  // namespace ivis::app
