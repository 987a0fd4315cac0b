#include <ivis/core/surface_source.h>

#include <ivis/core/errors.h>
#include <ivis/core/file_extension.h>
#include <ivis/core/hole_capping.h>
#include <ivis/core/hot_spots.h>
#include <ivis/core/log.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/core/pvd_reader.h>
#include <ivis/core/show_array.h>

#include <filesystem>

namespace ivis::core {
namespace {
bool isScene(const std::string& source) { return source.rfind(kScenePrefix, 0) == 0; }

/// Logs @a note, or adds it to @a notes when given.
void say(const std::string& note, std::vector<std::string>* notes)
{
    if (notes) notes->push_back(note);
    else logInfo(note);
}

/// Caps holes when asked, normalises and puts the hot spots on: the steps after a surface is read
/// or generated.
SurfaceField finishSurface(const std::string& source, SurfaceField field, const SurfaceLoadOptions& options,
                           std::vector<std::string>* notes)
{
    if (options.capHoles) {
        const std::size_t loops = capHoles(field);
        if (loops > 0) say(source + ": capped " + std::to_string(loops) + " boundary loops", notes);
    }
    if (options.frame) normalizeBy(field, *options.frame);
    else normalize(field);
    if (options.hotSpots > 0) {
        field.values = hotSpotValues(field.mesh, placeHotSpots(field.mesh, options.hotSpots));
        field.valuesOn = Association::Point;
        field.name = "hotspots";
    }
    return field;
}

}  // namespace

bool isTimeSeries(const std::string& source)
{
    return lowerCaseExtension(source) == ".pvd";
}

SurfaceField loadSurface(const std::string& source, const SurfaceLoadOptions& options)
{
    if (isScene(source)) {
        if (!options.read.scalarName.empty() || !options.read.scalarFile.empty() || options.read.cellToPoint)
            throw InputError(source + ": generated scenes carry their own scalar; --scalar, --scalar-file and "
                                      "--cell-to-point apply to mesh files only");
        return finishSurface(source, makeScene(source.substr(std::string(kScenePrefix).size())), options, nullptr);
    }
    if (isTimeSeries(source)) {
        const std::vector<TimeStep> steps = readPvd(source);
        throw InputError(source + ": a time series of " + std::to_string(steps.size()) +
                         (steps.size() == 1 ? " step" : " steps") + "; this command takes one step's file, such as " +
                         steps.front().path + " (render, optimize and the viewer take series)");
    }
    if (isArrayPattern(options.read.scalarName)) {
        throw InputError(source + ": --scalar '" + options.read.scalarName +
                         "' is a pattern, which makes a time series of the arrays it matches; this command shows "
                         "one array (render, optimize and the viewer take series)");
    }
    if (options.hotSpots > 0 && options.read.cellToPoint)
        throw InputError(source + ": --cell-to-point averages a cell array; hot spots are one value per vertex");
    MeshReadReport report;
    SurfaceField field = readMesh(source, options.read, &report);
    return loadReadSurface(source, std::move(field), report, options);
}

SurfaceField loadReadSurface(const std::string& source, SurfaceField field, const MeshReadReport& report,
                             const SurfaceLoadOptions& options, std::vector<std::string>* notes)
{
    for (const std::string& note : report.notes) say(source + ": " + note, notes);
    if (report.degenerateDropped > 0)
        say(source + ": dropped " + std::to_string(report.degenerateDropped) + " degenerate triangles", notes);
    if (report.unusedPointsDropped > 0)
        say(source + ": left out " + std::to_string(report.unusedPointsDropped) +
                (report.unusedPointsDropped == 1 ? " point" : " points") +
                " that no triangle uses (they would widen the framing and the colour range)",
            notes);
    if (options.defaultArray && !field.hasScalar() && options.hotSpots == 0 &&
        (!field.arrays.empty() || options.read.cellToPoint)) {
        const DataArray& shown = defaultArray(field, options.read.cellToPoint);
        showArray(field, qualifiedArrayName(shown), options.read.cellToPoint);
        say(source + ": showing the " + associationName(shown.association) + " array '" + field.name +
                "' (choose another with --scalar NAME; `inversevis info` lists them)",
            notes);
    }
    return finishSurface(source, std::move(field), options, notes);
}

std::string sourceStem(const std::string& source)
{
    if (isScene(source)) return source.substr(std::string(kScenePrefix).size());
    return std::filesystem::path(source).stem().string();
}

}  // namespace ivis::core
