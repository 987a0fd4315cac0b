// `inversevis merge PART.json...`: joins the --json files of `evaluate` jobs (each run with --only
// or on some of the meshes) into the results and tables one `evaluate` of them all would write.
#include "commands.h"
#include "evaluation_report.h"
#include "json_output.h"
#include "mesh_options.h"
#include "output_files.h"

#include <ivis/core/errors.h>
#include <ivis/core/json_text.h>
#include <ivis/render/method_registry.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <utility>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ivis::app {
namespace {

/// Why @a entry (of method @a method) is not one evaluate writes, or "": a known method, its
/// measures numbers from 0 to 1, its seconds keyed by resolutions.
std::string entryProblem(const std::string& method, const nlohmann::json& entry)
{
    const std::vector<std::string> methods = render::methodNames();
    if (std::find(methods.begin(), methods.end(), method) == methods.end()) return "no method is named " + method;
    if (!entry.is_object() || !entry.contains("seconds") || !entry.at("seconds").is_object())
        return "it holds no evaluation";
    for (const char* key : {"visibility", "front_visibility", "voxel_visibility", "paper_literal", "coherence"}) {
        const nlohmann::json* value = entry.contains(key) ? &entry.at(key) : nullptr;
        if (value == nullptr || !value->is_number() || !(value->get<double>() >= 0.0 && value->get<double>() <= 1.0))
            return std::string("its ") + key + " is not a number from 0 to 1";
    }
    for (const auto& [resolution, seconds] : entry.at("seconds").items())
        if (resolution.empty() || resolution.find_first_not_of("0123456789") != std::string::npos ||
            resolution.size() > 5 || !seconds.is_number())
            return "its seconds are not numbers keyed by resolutions";
    return "";
}

/// The results object of an evaluate --json file, each entry checked (and its tables made once,
/// so that anything else amiss is found here, naming the file).
nlohmann::json readPart(const std::string& path)
{
    if (std::filesystem::is_directory(path)) throw InputError(path + ": a folder, not an evaluate --json file");
    std::ifstream in(path);
    if (!in) throw InputError(path + (std::filesystem::exists(path) ? ": cannot open" : ": file not found"));
    nlohmann::json part = nlohmann::json::parse(in, nullptr, false);
    if (!part.is_object()) throw InputError(path + ": not the JSON of an evaluation");
    if (part.empty()) throw InputError(path + ": holds no evaluation (an empty object)");  // made empty tables
    ReportLayout layout;
    std::set<int> resolutions;
    for (const auto& [stem, methods] : part.items()) {
        if (!methods.is_object()) throw InputError(path + ": '" + stem + "' is not an object of methods");
        layout.stems.push_back(stem);
        for (const auto& [method, entry] : methods.items()) {
            if (const std::string problem = entryProblem(method, entry); !problem.empty())
                throw InputError(path + ": " + stem + ":" + method + " is not an evaluation's (" + problem + ")");
            if (std::find(layout.methods.begin(), layout.methods.end(), method) == layout.methods.end())
                layout.methods.push_back(method);
            for (const auto& seconds : entry.at("seconds").items()) resolutions.insert(std::stoi(seconds.key()));
        }
    }
    layout.optResolutions.assign(resolutions.begin(), resolutions.end());
    try {
        evaluationMarkdown(part, layout);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": not the JSON of an evaluation (" + core::jsonErrorWords(e) + ")");
    }
    return part;
}

}  // namespace

Command addMergeCommand(CLI::App& app)
{
    struct Options {
        std::vector<std::string> parts;
        std::string json, markdown;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "merge", "Join the --json files of evaluate jobs (--only MESH:METHOD) into one evaluation's JSON and tables");
    command->add_option("parts", options->parts, "evaluate --json files")->required();
    command->add_option("--json", options->json, "The joined results as JSON");
    command->add_option("--markdown", options->markdown, "The tables as Markdown (also printed)");

    return {command, [options] {
        std::vector<InputFile> parts;
        for (const std::string& part : options->parts) parts.push_back({part, "a part"});
        checkOutputFiles({jsonOutput(options->json, "--json"), markdownOutput(options->markdown, "--markdown")}, parts);
        nlohmann::json results = nlohmann::json::object();
        ReportLayout layout;
        std::set<std::string> methodsSeen;
        std::set<int> resolutions;
        std::vector<int> displayResolutions;
        std::map<std::string, std::string> source;  // "stem:method" -> the part that holds it
        // stem ("" for any) -> its first entry's "stem:method" and settings
        std::map<std::string, std::pair<std::string, nlohmann::json>> firstOf;
        for (const std::string& path : options->parts) {
            const nlohmann::json part = readPart(path);
            for (const auto& [stem, methods] : part.items()) {
                if (!results.contains(stem)) {
                    results[stem] = nlohmann::json::object();
                    layout.stems.push_back(stem);
                }
                for (const auto& [method, entry] : methods.items()) {
                    const std::string key = stem + ":" + method;
                    if (source.count(key)) throw InputError(path + ": " + key + " is in " + source.at(key) + " too");
                    source[key] = path;
                    // Every entry shares the first one's settings, and its mesh's first entry's all of them.
                    const nlohmann::json settings = entry.value("settings", nlohmann::json());
                    for (const std::string& of : {std::string(), stem}) {
                        const auto& [first, firstSettings] = firstOf.emplace(of, std::pair{key, settings}).first->second;
                        if (const std::string difference = settingsDifference(settings, firstSettings, !of.empty());
                            !difference.empty())
                            throw InputError(path + ": " + key + " was evaluated with " + difference + " in " +
                                             source.at(first) + " (" + first +
                                             "); merge parts of one evaluation, evaluated with the same options");
                    }
                    results[stem][method] = entry;
                    methodsSeen.insert(method);
                    for (const auto& seconds : entry.at("seconds").items()) resolutions.insert(std::stoi(seconds.key()));
                    displayResolutions.push_back(entry.value("display_res", layout.displayResolution));
                }
            }
        }
        if (std::adjacent_find(displayResolutions.begin(), displayResolutions.end(), std::not_equal_to<>()) !=
            displayResolutions.end())
            throw InputError("the parts were measured at different --display-res; merge parts of one evaluation");
        if (!displayResolutions.empty()) layout.displayResolution = displayResolutions.front();
        for (const std::string& method : render::methodNames())  // the registry's order, as evaluate's default
            if (methodsSeen.erase(method)) layout.methods.push_back(method);
        layout.methods.insert(layout.methods.end(), methodsSeen.begin(), methodsSeen.end());
        layout.optResolutions.assign(resolutions.begin(), resolutions.end());

        if (!options->json.empty()) writeJsonFile(results, options->json);
        const std::string markdown = evaluationMarkdown(results, layout);
        if (!options->markdown.empty()) writeTextFile(markdown, options->markdown);
        std::cout << markdown;
    }};
}

}  // namespace ivis::app
