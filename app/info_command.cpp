// `inversevis info MESH`: what a mesh file (or a time series) carries.
#include "commands.h"

#include <ivis/core/errors.h>
#include <ivis/core/json_text.h>
#include <ivis/core/mesh_reader.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/pvd_reader.h>
#include <ivis/core/surface_source.h>
#include <ivis/core/utf8.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>

namespace ivis::app {
namespace {

/// A series' arrays: each (name, association) of any step, its range over the steps that have it.
struct SeriesArray {
    core::ArrayInfo info;  ///< min, max and NaN count over the steps
    std::size_t steps = 0;  ///< how many steps carry it
};

/// The arrays of every step of a series, in the first step's order (then any later step's); shown
/// by default is the first step's default, which a series' pictures show.
std::vector<SeriesArray> seriesArrays(const std::vector<core::TimeStep>& steps)
{
    std::vector<SeriesArray> arrays;
    for (const core::TimeStep& step : steps)
        for (core::ArrayInfo a : core::describeMesh(step.path).arrays) {
            auto same = std::find_if(arrays.begin(), arrays.end(), [&](const SeriesArray& s) {
                return s.info.name == a.name && s.info.association == a.association;
            });
            if (same == arrays.end()) {
                a.shownByDefault = a.shownByDefault && &step == &steps.front();
                arrays.push_back({a, 1});
                continue;
            }
            same->info.min = std::fmin(same->info.min, a.min);  // NaN (no finite value) gives way
            same->info.max = std::fmax(same->info.max, a.max);
            same->info.nanCount += a.nanCount;
            ++same->steps;
        }
    return arrays;
}

/// One array as `info --json` lists it.
nlohmann::json arrayJson(const core::ArrayInfo& a)
{
    return {{"name", a.name},
            {"association", core::associationName(a.association)},
            {"type", core::valueTypeName(a.type)},
            {"components", a.components},
            {"min", std::isnan(a.min) ? nlohmann::json() : nlohmann::json(a.min)},
            {"max", std::isnan(a.max) ? nlohmann::json() : nlohmann::json(a.max)},
            {"nan_count", a.nanCount},
            {"shown_by_default", a.shownByDefault}};
}

/// How many terminal columns the UTF-8 character starting with code point @a c takes: two for
/// the East Asian wide and full-width ranges (CJK, Hangul, full-width forms), else one.
std::size_t columnsOf(std::uint32_t c)
{
    const bool wide = (c >= 0x1100 && c <= 0x115F) || (c >= 0x2E80 && c <= 0xA4CF) || (c >= 0xAC00 && c <= 0xD7A3) ||
                      (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F) || (c >= 0xFF00 && c <= 0xFF60) ||
                      (c >= 0xFFE0 && c <= 0xFFE6) || (c >= 0x20000 && c <= 0x3FFFD);
    return wide ? 2 : 1;
}

/// @a text followed by spaces up to @a width terminal columns (UTF-8 characters, not bytes, and
/// wide ones as two, so that a name such as "τ_w" or "壁面せん断応力" keeps the columns after it aligned).
std::string padded(const std::string& text, std::size_t width)
{
    std::size_t columns = 0;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t length = core::utf8Length(text, i);  // a byte that is not UTF-8 shows as one
        columns += length == 0 ? 1 : columnsOf(core::utf8CodePoint(text, i, length));
        i += length == 0 ? 1 : length;
    }
    return text + std::string(columns < width ? width - columns : 0, ' ');
}

/// One array as `info` prints it, on a line of its own.
void printArray(const core::ArrayInfo& a)
{
    std::cout << "    " << padded(a.name, 20) << "  " << padded(core::associationName(a.association), 5) << "  "
              << padded(core::valueTypeName(a.type), 7) << "  " << a.components
              << (a.components == 1 ? " component " : " components") << "  "
              << (a.components == 1 ? "" : "magnitude ");
    if (std::isnan(a.min))
        std::cout << "no finite value";
    else
        std::cout << "min " << a.min << "  max " << a.max;
    if (a.nanCount > 0) std::cout << "  (" << a.nanCount << " NaN)";
    if (a.shownByDefault) std::cout << "  (shown by default)";
}

/// The time steps of a .pvd and their arrays (each one's range over every step), as JSON or text.
void printTimeSeries(const std::string& path, bool json)
{
    const std::vector<core::TimeStep> steps = core::readPvd(path);
    const std::vector<SeriesArray> arrays = seriesArrays(steps);
    if (json) {
        nlohmann::json list = nlohmann::json::array(), arrayList = nlohmann::json::array();
        for (const core::TimeStep& s : steps)
            list.push_back({{"time", s.timed ? nlohmann::json(s.time) : nlohmann::json()}, {"file", s.path}});
        for (const SeriesArray& a : arrays) {
            nlohmann::json entry = arrayJson(a.info);
            entry["steps"] = a.steps;
            arrayList.push_back(entry);
        }
        const nlohmann::json out = {{"path", path}, {"format", "pvd"}, {"time_steps", list}, {"arrays", arrayList}};
        std::cout << core::jsonText(out, 2) << "\n";
        return;
    }
    std::cout << path << " (pvd, " << steps.size() << (steps.size() == 1 ? " time step)\n" : " time steps)\n");
    for (const core::TimeStep& s : steps)
        std::cout << "  " << (s.timed ? "t = " : "step ") << s.time << "  " << s.path << "\n";
    std::cout << "  arrays (range over the steps)" << (arrays.empty() ? "  none" : "") << "\n";
    for (const SeriesArray& a : arrays) {
        printArray(a.info);
        if (a.steps < steps.size()) std::cout << "  (in " << a.steps << " of " << steps.size() << " steps)";
        std::cout << "\n";
    }
}

void printJson(const core::MeshInfo& info)
{
    nlohmann::json arrays = nlohmann::json::array();
    for (const core::ArrayInfo& a : info.arrays) arrays.push_back(arrayJson(a));
    const nlohmann::json out = {{"path", info.path},
                                {"format", info.format},
                                {"vertices", info.vertices},
                                {"cells", info.cells},
                                {"triangles", info.triangles},
                                {"degenerate_dropped", info.report.degenerateDropped},
                                {"unused_points", info.report.unusedPointsDropped},
                                {"boundary_edges", info.boundaryEdges},
                                {"open_mesh", info.boundaryEdges > 0},
                                {"components", info.components},
                                {"bbox_min", {info.bounds.lo.x, info.bounds.lo.y, info.bounds.lo.z}},
                                {"bbox_max", {info.bounds.hi.x, info.bounds.hi.y, info.bounds.hi.z}},
                                {"mesh_units", core::meshUnitsJson(core::normalizingTransform(info.bounds))},
                                {"arrays", arrays},
                                {"notes", info.report.notes}};
    std::cout << core::jsonText(out, 2) << "\n";
}

void printText(const core::MeshInfo& info)
{
    std::cout << info.path << " (" << info.format << ")\n"
              << "  vertices        " << info.vertices;
    if (info.report.unusedPointsDropped > 0)
        std::cout << " (" << info.report.unusedPointsDropped << " used by no triangle, left out)";
    std::cout << "\n  cells           " << info.cells << "\n"
              << "  triangles       " << info.triangles;
    if (info.report.degenerateDropped > 0) std::cout << " (" << info.report.degenerateDropped << " degenerate dropped)";
    std::cout << "\n  boundary edges  " << info.boundaryEdges << (info.boundaryEdges > 0 ? " (open)" : " (closed)")
              << "\n  components      " << info.components << "\n  bounding box    [" << info.bounds.lo.x << ", "
              << info.bounds.lo.y << ", " << info.bounds.lo.z << "] .. [" << info.bounds.hi.x << ", "
              << info.bounds.hi.y << ", " << info.bounds.hi.z << "]\n";
    const core::Similarity units = core::normalizingTransform(info.bounds);
    std::cout << "  normalised as   (p - [" << units.center.x << ", " << units.center.y << ", " << units.center.z
              << "]) * " << units.scale << "  (pictures, cameras and EXR positions; mesh = p / "
              << units.scale << " + center)\n  arrays          ";
    if (info.arrays.empty()) std::cout << "none";
    std::cout << "\n";
    for (const core::ArrayInfo& a : info.arrays) {
        printArray(a);
        std::cout << "\n";
    }
    for (const std::string& note : info.report.notes) std::cout << "  note: " << note << "\n";
}

}  // namespace

Command addInfoCommand(CLI::App& app)
{
    struct Options {
        std::string path;
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command =
        app.add_subcommand("info", "List what a mesh carries: counts, boundary, bounds, point and cell arrays");
    command->add_option("mesh", options->path, "Mesh file (.obj .off .ply .stl .vtk .vtp .vtu) or time series (.pvd)")
        ->required();
    command->add_flag("--json", options->json, "Print one JSON object");

    return {command, [options] {
        if (options->path.rfind(core::kScenePrefix, 0) == 0) {  // it said "file not found"
            core::checkSceneName(options->path.substr(std::string(core::kScenePrefix).size()));
            throw InputError(options->path + ": a generated scene, not a file: info lists what a mesh file carries "
                                             "(render it, or `sdf " + options->path + " --json` for its volume)");
        }
        if (core::isTimeSeries(options->path)) {
            printTimeSeries(options->path, options->json);
            return;
        }
        const core::MeshInfo info = core::describeMesh(options->path);
        if (options->json)
            printJson(info);
        else
            printText(info);
    }};
}

}  // namespace ivis::app
