// `inversevis merge PART.json...`: joins the --json files of `evaluate` jobs (each run with --only
// or on some of the meshes) into the results and tables one `evaluate` of them all would write.
#include "commands.h"
#include "evaluation_report.h"
#include "json_output.h"
#include "output_files.h"

#include <ivis/core/errors.h>
#include <ivis/render/method_registry.h>

#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace ivis::app {

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
        std::optional<std::pair<int, std::string>> display;  // the first entry's --display-res and its part
        std::map<std::string, std::string> source;  // "stem:method" -> the part that holds it
        // stem ("" for any) -> its first entry's "stem:method" and settings
        std::map<std::string, std::pair<std::string, nlohmann::json>> firstOf;
        for (const std::string& path : options->parts) {
            const nlohmann::json part = readEvaluationJson(path);
            if (part.empty()) throw InputError(path + ": holds no evaluation (an empty object)");
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
                    const int pixels = entry.value("display_res", layout.displayResolution);
                    if (!display) display.emplace(pixels, path);
                    if (pixels != display->first)
                        throw InputError(path + ": " + key + " was measured at --display-res " + std::to_string(pixels) +
                                         " against " + std::to_string(display->first) + " in " + display->second +
                                         "; merge parts of one evaluation");
                }
            }
        }
        if (display) layout.displayResolution = display->first;
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
