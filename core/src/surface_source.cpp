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
}  // namespace

bool isTimeSeries(const std::string& source)
{
    return lowerCaseExtension(source) == ".pvd";
}

SurfaceField loadSurface(const std::string& source, const SurfaceLoadOptions& options)
{
    SurfaceField field;
    if (isScene(source)) {
        if (!options.read.scalarName.empty() || !options.read.scalarFile.empty() || options.read.cellToPoint)
            throw InputError(source + ": generated scenes carry their own scalar; --scalar, --scalar-file and "
                                      "--cell-to-point apply to mesh files only");
        field = makeScene(source.substr(std::string(kScenePrefix).size()));
    } else if (isTimeSeries(source)) {
        const std::vector<TimeStep> steps = readPvd(source);
        throw InputError(source + ": a time series of " + std::to_string(steps.size()) +
                         (steps.size() == 1 ? " step" : " steps") + "; this command takes one step's file, such as " +
                         steps.front().path + " (render, optimize and the viewer take series)");
    } else if (isArrayPattern(options.read.scalarName)) {
        throw InputError(source + ": --scalar '" + options.read.scalarName +
                         "' is a pattern, which makes a time series of the arrays it matches; this command shows "
                         "one array (render, optimize and the viewer take series)");
    } else if (options.hotSpots > 0 && options.read.cellToPoint) {
        throw InputError(source + ": --cell-to-point averages a cell array; hot spots are one value per vertex");
    } else {
        MeshReadReport report;
        field = readMesh(source, options.read, &report);
        for (const std::string& note : report.notes) logInfo(source + ": " + note);
        if (report.degenerateDropped > 0) {
            logInfo(source + ": dropped " + std::to_string(report.degenerateDropped) + " degenerate triangles");
        }
        if (!field.hasScalar() && options.hotSpots == 0 && (!field.arrays.empty() || options.read.cellToPoint)) {
            const DataArray& shown = defaultArray(field, options.read.cellToPoint);
            showArray(field, qualifiedArrayName(shown), options.read.cellToPoint);
            logInfo(source + ": showing the " + associationName(shown.association) + " array '" + field.name +
                    "' (choose another with --scalar NAME; `inversevis info` lists them)");
        }
    }
    if (options.capHoles) {
        const std::size_t loops = capHoles(field);
        if (loops > 0) logInfo(source + ": capped " + std::to_string(loops) + " boundary loops");
    }
    normalize(field);
    if (options.hotSpots > 0) {
        field.values = hotSpotValues(field.mesh, placeHotSpots(field.mesh, options.hotSpots));
        field.valuesOn = Association::Point;
        field.name = "hotspots";
    }
    return field;
}

std::string sourceStem(const std::string& source)
{
    if (isScene(source)) return source.substr(std::string(kScenePrefix).size());
    return std::filesystem::path(source).stem().string();
}

}  // namespace ivis::core
