#include "mesh_options.h"

#include "cli_checks.h"
#include "method_options.h"

#include <ivis/core/errors.h>
#include <ivis/core/hot_spots.h>
#include <ivis/core/procedural_scenes.h>
#include <ivis/render/method_registry.h>

#include <cstdio>
#include <filesystem>


namespace ivis::app {

void MeshOptions::addTo(CLI::App& command, std::vector<std::string>* sources, const std::string& sourcesNote)
{
    std::string scenes;
    for (const std::string& scene : core::sceneNames()) scenes += (scenes.empty() ? "scene:" : "|") + scene;
    const std::string help = "Mesh file (.obj .off .ply .stl .vtk .vtp .vtu) or " + scenes;
    if (sources)
        command.add_option("meshes", *sources, help + "; " + sourcesNote)->required();
    else
        command.add_option("mesh", source, help)->required();
    auto* scalar = command.add_option("--scalar", load.read.scalarName,
                                      "Point or cell array to show: NAME (a vector by its magnitude), "
                                      "NAME:magnitude or NAME:0, NAME:1, ... for one component; cell:NAME or "
                                      "point:NAME for the one of that association");
    auto* scalarFile =
        command
            .add_option("--scalar-file", load.read.scalarFile,
                        "Text file with one value per vertex, in the file's vertex order (STL: the order in which "
                        "each merged corner first appears)")
            ->excludes(scalar);
    auto* cellToPoint =
        command
            .add_flag("--cell-to-point", load.read.cellToPoint,
                      "Show a cell array averaged onto the vertices (area-weighted) instead of flat per triangle "
                      "(without --scalar: the file's active cell scalars, else its first cell array)")
            ->excludes(scalarFile);
    command
        .add_option("--hotspots", load.hotSpots,
                    "Show N Gaussian hot spots instead of a scalar: the first two at the ends of the mesh's thinnest "
                    "principal axis, the next along the middle and the longest axis (reveal measure)")
        ->check(CLI::Range(1, core::kMaxHotSpots))
        ->excludes(scalar)
        ->excludes(scalarFile)
        ->excludes(cellToPoint);
    command.add_flag("--cap-holes", load.capHoles, "Close open boundary loops (caps are never coloured)");
    command.add_option("--volume-res", volume.resolution,
                       "Voxels across the box [-2.5,2.5]^3 (" + std::to_string(vdb::kMinResolution) + " to " +
                           std::to_string(vdb::kMaxResolution) + ")")
        ->check(CLI::Range(vdb::kMinResolution, vdb::kMaxResolution))
        ->capture_default_str();
    command.add_option("--band", volume.bandVoxels, "Fine narrow-band half-width in voxels")
        ->check(finiteRange(3.0, 64.0))
        ->capture_default_str();
    reachOption = command.add_option("--reach", volume.farFieldReach,
                                     "Exterior distance the far field covers (normalised; default 0.6, or more when the "
                                     "method's rays need it: inversevis-wrap's hull offset + 0.4, another curved-ray "
                                     "method's + 0.6; sdf: the default method's)")
                      ->check(positiveUpTo(vdb::kMaxFarFieldReach));
    command.add_option("--distance", distance, "Distance sign: auto (unsigned for open meshes), signed, unsigned")
        ->check(CLI::IsMember({"auto", "signed", "unsigned"}))
        ->capture_default_str();
}

bool MeshOptions::useViewScalar(const std::string& scalarName, const std::string& scalarFile, bool cellToPoint,
                                int hotSpots)
{
    if (!load.read.scalarName.empty() || !load.read.scalarFile.empty() || load.hotSpots > 0) {
        // The view file keeps --scalar-file as an absolute path.
        const std::string file =
            load.read.scalarFile.empty() ? "" : std::filesystem::absolute(load.read.scalarFile).string();
        return load.read.scalarName == scalarName && file == scalarFile && load.hotSpots == hotSpots;
    }
    load.read.scalarName = scalarName;
    load.read.scalarFile = scalarFile;
    load.read.cellToPoint = load.read.cellToPoint || cellToPoint;  // --cell-to-point alone averages the view's array
    load.hotSpots = hotSpots;
    return true;
}

nlohmann::json MeshOptions::settingsJson() const
{
    return {{"--scalar", load.read.scalarName},
            {"--scalar-file", load.read.scalarFile},
            {"--cell-to-point", load.read.cellToPoint},
            {"--hotspots", load.hotSpots},
            {"--cap-holes", load.capHoles},
            {"--volume-res", volume.resolution},
            {"--band", volume.bandVoxels},
            {"--reach", reachOption && reachOption->count() > 0 ? nlohmann::json(volume.farFieldReach) : nlohmann::json()},
            {"--distance", distance}};
}

vdb::VolumeOptions MeshOptions::volumeOptions() const
{
    vdb::VolumeOptions options = volume;
    options.sign = distance == "signed"     ? vdb::DistanceSign::Signed
                   : distance == "unsigned" ? vdb::DistanceSign::Unsigned
                                            : vdb::DistanceSign::Auto;
    vdb::validate(options);
    return options;
}

void MeshOptions::raiseReachFor(const std::vector<render::MethodPtr>& methods)
{
    if (reachOption && reachOption->count() > 0) return;  // --reach given: checkMethodFitsVolume judges it
    for (const render::MethodPtr& method : methods)
        if (method->reachNeeded() > vdb::kMaxFarFieldReach) {  // the curved rays' hull and their room beyond it
            const double hull = method->values().at("hull_offset").at(0);
            const double excess = method->reachNeeded() - vdb::kMaxFarFieldReach;
            char text[240];
            std::snprintf(text, sizeof text,
                          "%s --hull-offset %.3g needs a volume reaching %.3g, beyond the largest (%g): at most %.3g "
                          "(or give --reach)",
                          method->name().c_str(), hull, double(method->reachNeeded()), vdb::kMaxFarFieldReach,
                          hull - excess);
            throw ValueError(text);
        }
    volume.farFieldReach = render::reachNeededBy(methods, volume.farFieldReach);
}

void MeshOptions::fitReachTo(const std::vector<render::MethodPtr>& methods)
{
    raiseReachFor(methods);
    const vdb::VolumeOptions options = volumeOptions();
    for (const render::MethodPtr& method : methods) checkMethodFitsVolume(*method, options);
}

}  // namespace ivis::app
