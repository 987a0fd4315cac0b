// `inversevis sdf MESH`: build or reuse the cached sparse volume and report it.
#include "cli_checks.h"
#include "commands.h"
#include "mesh_options.h"
#include "output_files.h"

#include <ivis/core/json_text.h>
#include <ivis/core/log.h>
#include <ivis/core/progress_bar.h>
#include <ivis/render/method_registry.h>
#include <ivis/vdb/cache_folder.h>
#include <ivis/vdb/volume_cache.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <memory>

namespace ivis::app {

Command addSdfCommand(CLI::App& app)
{
    struct Options {
        MeshOptions mesh;
        std::string output;
        std::string cacheDir;
        bool json = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("sdf", "Build the sparse distance / triangle / gradient volume");
    options->mesh.addTo(*command);
    command->add_option("-o,--output", options->output,
                        "Volume file (default: <mesh>.<mesh hash>.res<N>.reach<R>[.band<B>][.signed|.unsigned].vdb in the cache folder, where render, "
                        "optimize, evaluate and the viewer find it)");
    command->add_option("--cache-dir", options->cacheDir, kCacheDirHelp)->check(nonEmpty())
        ->excludes("--output");  // -o writes the volume to its own file: no cache folder is used
    command->add_flag("--json", options->json, "Print one JSON object");

    return {command, [options] {
        const auto start = std::chrono::steady_clock::now();
        checkOutputFiles({{options->output, "-o", {".vdb"}}});
        options->mesh.raiseReachFor({render::defaultMethod()});  // the volume `render` uses by default
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        // The cache is sdf's output: a folder it cannot write is refused before the mesh is read.
        const std::string folder = options->output.empty() ? vdb::writableCacheFolder(options->cacheDir) : "";
        options->mesh.load.defaultArray = false;  // the volume shows no scalar: no note of one
        const core::SurfaceField field = core::loadSurface(options->mesh.source, options->mesh.load);
        const std::string path = options->output.empty()
                                     ? vdb::defaultVolumePath(folder, options->mesh.source, field.mesh, volumeOptions)
                                     : options->output;
        vdb::CacheOutcome outcome{};
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info && !options->json);
        const vdb::SurfaceVolume volume =
            vdb::loadOrBuildVolume(field.mesh, volumeOptions, path, &progress, &outcome);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        const nlohmann::json out = {
            {"output", path},
            {"cache", vdb::toString(outcome)},
            {"resolution", volume.options.resolution},
            {"voxel_size", volume.voxelSize()},
            {"voxel_size_mesh_units", field.normalization.meshLength(volume.voxelSize())},
            {"mesh_units", core::meshUnitsJson(field.normalization)},
            {"band_voxels", volume.options.bandVoxels},
            {"far_field_resolution", volume.farPhi ? volume.options.farFieldResolution : volume.options.resolution},
            {"reach", volume.reach()},
            {"active_voxels", volume.activeVoxels()},
            {"band_voxels_active", volume.phi->activeVoxelCount()},
            {"memory_bytes", volume.memoryBytes()},
            {"seconds", seconds},
            {"open_mesh", core::boundaryEdgeCount(field.mesh) > 0},
            {"unsigned_distance", volume.unsignedDistance},
            {"triangles", volume.triangleCount}};
        if (options->json) {
            std::cout << core::jsonText(out, 2) << "\n";
            return;
        }
        core::logInfo(path + ": " + vdb::toString(outcome) + ", N=" + std::to_string(volume.options.resolution) +
                      ", " + std::to_string(volume.activeVoxels()) + " active voxels, " +
                      std::to_string(volume.memoryBytes() >> 20) + " MiB, " + std::to_string(seconds) + " s" +
                      (volume.unsignedDistance ? ", unsigned distance (open mesh)" : ""));
    }};
}

}  // namespace ivis::app
