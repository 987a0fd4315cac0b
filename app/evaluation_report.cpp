#include "evaluation_report.h"

#include <ivis/core/errors.h>
#include <ivis/core/json_text.h>
#include <ivis/render/method_registry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

namespace ivis::app {
namespace {

/// @a name as a Markdown table cell: '|' escaped, which would end the cell, and line breaks as spaces.
std::string tableCell(const std::string& name)
{
    std::string cell;
    for (char c : name) {
        if (c == '|') cell += "\\|";
        else cell += c == '\n' || c == '\r' ? ' ' : c;
    }
    return cell;
}

std::string percent(double fraction)
{
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%.1f", 100.0 * fraction);
    return buffer;
}

std::string fixed(double value, int digits)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

/// "total (direct) [region, region, ...]" in percent, or "-" without a reveal.
std::string revealText(const nlohmann::json& entry)
{
    if (!entry.contains("reveal")) return "-";
    const nlohmann::json& reveal = entry.at("reveal");
    if (reveal.is_null()) return "no important surface";
    std::string text = percent(reveal.at("total")) + " (" + percent(reveal.at("direct")) + ") [";
    const nlohmann::json& regions = reveal.at("per_region");
    for (std::size_t i = 0; i < regions.size(); ++i) text += (i ? ", " : "") + percent(regions[i]);
    return text + "]";
}

/// "share/ratio, share/ratio" of each hot spot's shape in the picture, or "-" without them.
std::string shapesText(const nlohmann::json& entry)
{
    if (!entry.contains("reveal") || entry.at("reveal").is_null() || !entry.at("reveal").contains("shapes")) return "-";
    std::string text;
    for (const nlohmann::json& shape : entry.at("reveal").at("shapes"))
        text += (text.empty() ? "" : ", ") + fixed(shape.at("largest_share"), 2) + "/" + fixed(shape.at("outline_ratio"), 2);
    return text;
}

/// "99.9 (98.8, 98.0)": the surface several views show together and each alone, in percent, or "-".
std::string severalViewsText(const nlohmann::json& entry)
{
    if (!entry.contains("several_views")) return "-";
    const nlohmann::json& several = entry.at("several_views");
    std::string each;
    for (const nlohmann::json& view : several.at("views"))
        each += (each.empty() ? "" : ", ") + percent(view.at("visibility")) + " / " + fixed(view.at("coherence"), 3);
    return percent(several.at("union").at("visibility")) + " (" + each + ")";
}

/// A Markdown table with a row per mesh and a column per method, each cell @a cell(entry).
std::string methodTable(const nlohmann::json& results, const ReportLayout& layout,
                        const std::function<std::string(const nlohmann::json&)>& cell)
{
    std::ostringstream text;
    text << "| Surface |";
    for (const auto& m : layout.methods) text << " " << m << " |";
    text << "\n|---|";
    for (std::size_t i = 0; i < layout.methods.size(); ++i) text << "---|";
    text << "\n";
    for (const std::string& stem : layout.stems) {
        if (!results.contains(stem)) continue;
        text << "| " << tableCell(stem) << " |";
        for (const auto& m : layout.methods) {
            const nlohmann::json& row = results.at(stem);
            text << " " << (row.contains(m) ? cell(row.at(m)) : std::string("-")) << " |";  // -: not evaluated
        }
        text << "\n";
    }
    return text.str();
}

/// Table 2: seconds per method and optimisation resolution.
std::string secondsTable(const nlohmann::json& results, const ReportLayout& layout)
{
    std::ostringstream text;
    text << "| Surface |";
    for (const auto& m : layout.methods)
        for (int r : layout.optResolutions) text << " " << m << " " << r << " |";
    text << "\n|---|";
    for (std::size_t i = 0; i < layout.methods.size() * layout.optResolutions.size(); ++i) text << "---|";
    text << "\n";
    for (const std::string& stem : layout.stems) {
        if (!results.contains(stem)) continue;
        text << "| " << tableCell(stem) << " |";
        for (const auto& m : layout.methods)
            for (int r : layout.optResolutions) {
                const nlohmann::json& row = results.at(stem);
                const std::string key = std::to_string(r);
                if (row.contains(m) && row.at(m).at("seconds").contains(key))
                    text << " " << fixed(row.at(m).at("seconds").at(key).get<double>(), 1) << " |";
                else
                    text << " - |";
            }
        text << "\n";
    }
    return text.str();
}

/// Why @a entry (of method @a method) is not one evaluate writes, or "": a known method, its
/// measures numbers from 0 to 1, its seconds keyed by resolutions, its display resolution (when
/// given) a whole number of pixels.
std::string entryProblem(const std::string& method, const nlohmann::json& entry)
{
    const std::vector<std::string> methods = render::methodNames();
    if (std::find(methods.begin(), methods.end(), method) == methods.end()) return "no method is named " + oneLine(method);
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
    if (entry.contains("display_res")) {
        const nlohmann::json& pixels = entry.at("display_res");
        if (!pixels.is_number_integer() || !(pixels.get<long long>() >= 1 && pixels.get<long long>() <= 100000))
            return "its display_res is not a whole number of pixels";
    }
    return "";
}

}  // namespace

nlohmann::json detail::parseEvaluationJson(const std::string& path, const std::string& text)
{
    nlohmann::json results = nlohmann::json::parse(text, nullptr, false);
    if (!results.is_object()) throw InputError(path + ": not the JSON of an evaluation");
    ReportLayout layout;
    std::set<int> resolutions;
    for (const auto& [stem, methods] : results.items()) {
        // A mesh's name is a file's stem: a line break in one would break every message naming it.
        if (std::any_of(stem.begin(), stem.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
            throw InputError(path + ": '" + oneLine(stem) + "' is not a mesh's name (it holds a control character)");
        if (!methods.is_object()) throw InputError(path + ": '" + stem + "' is not an object of methods");
        layout.stems.push_back(stem);
        for (const auto& [method, entry] : methods.items()) {
            if (const std::string problem = entryProblem(method, entry); !problem.empty())
                throw InputError(path + ": " + stem + ":" + oneLine(method) + " is not an evaluation's (" + problem + ")");
            if (std::find(layout.methods.begin(), layout.methods.end(), method) == layout.methods.end())
                layout.methods.push_back(method);
            for (const auto& seconds : entry.at("seconds").items()) resolutions.insert(std::stoi(seconds.key()));
        }
    }
    layout.optResolutions.assign(resolutions.begin(), resolutions.end());
    try {
        evaluationMarkdown(results, layout);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": not the JSON of an evaluation (" + core::jsonErrorWords(e) + ")");
    }
    return results;
}

nlohmann::json readEvaluationJson(const std::string& path)
{
    if (std::filesystem::is_directory(path)) throw InputError(path + ": a folder, not an evaluate --json file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + (std::filesystem::exists(path) ? ": cannot open" : ": file not found"));
    std::ostringstream text;
    text << in.rdbuf();
    return detail::parseEvaluationJson(path, text.str());
}

std::string evaluationMarkdown(const nlohmann::json& results, const ReportLayout& layout)
{
    bool anyReveal = false;
    for (const std::string& stem : layout.stems)
        if (results.contains(stem))
            for (const auto& m : layout.methods)
                anyReveal |= results.at(stem).contains(m) && results.at(stem).at(m).contains("reveal");
    std::string markdown =
        "## Surface visibility in percent of the area at each method's best view (front-only in brackets)\n\n" +
        methodTable(results, layout, [](const nlohmann::json& e) {
            return percent(e.at("visibility")) + " (" + percent(e.at("front_visibility")) + ")";
        }) +
        "\n## Surface visibility in percent of the surface voxels (voxel_visibility), same views\n\n" +
        methodTable(results, layout, [](const nlohmann::json& e) { return percent(e.at("voxel_visibility")); }) +
        "\n## Paper-literal visibility in percent (visited / marked voxels), same views\n\n" +
        methodTable(results, layout, [](const nlohmann::json& e) { return percent(e.at("paper_literal")); }) +
        "\n## Mapping coherence at " + std::to_string(layout.displayResolution) + "^2 pixels, same views\n\n" +
        methodTable(results, layout, [](const nlohmann::json& e) { return fixed(e.at("coherence"), 3); });
    if (anyReveal)
        markdown += "\n## Hot-spot reveal in percent of the important area: total (direct) [each region]\n\n" +
                    methodTable(results, layout, revealText) +
                    "\n## Hot spots as one place in the picture: share in the largest 4-connected region / outline over "
                    "convex-hull perimeter, per region\n\n" +
                    methodTable(results, layout, shapesText);
    bool anySeveral = false;
    for (const std::string& stem : layout.stems)
        if (results.contains(stem))
            for (const auto& m : layout.methods)
                anySeveral |= results.at(stem).contains(m) && results.at(stem).at(m).contains("several_views");
    if (anySeveral)
        markdown += "\n## Several views: surface visibility in percent of what they show together (each view: "
                    "visibility / coherence)\n\n" +
                    methodTable(results, layout, severalViewsText);
    return markdown + "\n## Viewpoint optimisation, seconds per optimisation resolution\n\n" + secondsTable(results, layout);
}

std::string settingsDifference(const nlohmann::json& a, const nlohmann::json& b, bool sameMesh)
{
    const char* old = "none (an evaluation of before 2026-11-27)";
    if (!a.is_object() || !b.is_object())
        return a.is_object() == b.is_object() ? "" : a.is_object() ? std::string("settings against ") + old
                                                                    : std::string(old) + " against settings";
    const std::set<std::string> meshSettings{"mesh hash",  "--scalar",    "--scalar-file", "--cell-to-point",
                                             "--hotspots", "--cap-holes", "--distance"};
    auto shown = [](const nlohmann::json& value) { return value.is_null() ? std::string("unset") : value.dump(); };
    // --views is written only above 1 (and every method has it): an entry without it had one view.
    auto views = [](const nlohmann::json& s) { return s.contains("--views") ? s.at("--views") : nlohmann::json(1); };
    if (views(a) != views(b)) return "--views " + shown(views(a)) + " against " + shown(views(b));
    // A flag one entry lacks is not its method's (--alpha-scan of a method without alpha).
    for (const auto& [flag, value] : a.items())
        if (b.contains(flag) && (sameMesh || meshSettings.count(flag) == 0) && value != b.at(flag))
            return oneLine(flag) + " " + shown(value) + " against " + shown(b.at(flag));  // one line, whatever the file holds
    return "";
}

}  // namespace ivis::app
