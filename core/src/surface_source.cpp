#include <ivis/core/surface_source.h>

#include <ivis/core/errors.h>
#include <ivis/core/hole_capping.h>
#include <ivis/core/hot_spots.h>
#include <ivis/core/log.h>
#include <ivis/core/procedural_scenes.h>

#include <filesystem>

namespace ivis::core {
namespace {
bool isScene(const std::string& source) { return source.rfind(kScenePrefix, 0) == 0; }
}  // namespace

SurfaceField loadSurface(const std::string& source, const SurfaceLoadOptions& options)
{
    SurfaceField field;
    if (isScene(source)) {
        if (!options.read.scalarName.empty() || !options.read.scalarFile.empty())
            throw InputError(source + ": generated scenes carry their own scalar; --scalar and --scalar-file "
                                      "apply to mesh files only");
        field = makeScene(source.substr(std::string(kScenePrefix).size()));
    } else {
        std::size_t dropped = 0;
        field = readMesh(source, options.read, &dropped);
        if (dropped > 0) logInfo(source + ": dropped " + std::to_string(dropped) + " degenerate triangles");
    }
    if (options.capHoles) {
        const std::size_t loops = capHoles(field);
        if (loops > 0) logInfo(source + ": capped " + std::to_string(loops) + " boundary loops");
    }
    normalize(field);
    if (options.hotSpots > 0) {
        field.values = hotSpotValues(field.mesh, placeHotSpots(field.mesh, options.hotSpots));
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
