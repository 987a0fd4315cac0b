// `inversevis render MESH`: one picture of a method, with optional EXR layers, stats and camera.
#include "commands.h"
#include "json_output.h"
#include "mesh_options.h"
#include "view_options.h"

#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/core/progress_bar.h>
#include <ivis/optimize/coherence.h>
#include <ivis/render/method_json.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/volume_cache.h>

#include <nlohmann/json.hpp>

#include <memory>

namespace ivis::app {

Command addRenderCommand(CLI::App& app)
{
    struct Options {
        MeshOptions mesh;
        ViewOptions view;
        std::string output = "inversevis.png";
        std::string exr;
        std::string statsJson;
        std::string cameraOut;
        std::string cacheDir;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("render", "Render a method's picture to PNG (and EXR layers)");
    options->mesh.addTo(*command);
    options->view.addTo(*command);
    command->add_option("-o,--output", options->output, "PNG file")->capture_default_str();
    command->add_option("--exr", options->exr, "Multi-layer OpenEXR file (linear colour + per-pixel layers)");
    command->add_option("--stats-json", options->statsJson, "Write render statistics as JSON");
    command->add_option("--camera-out", options->cameraOut, "Camera JSON written (default: <output>.camera.json)");
    command->add_option("--cache-dir", options->cacheDir, "Folder for volume caches (default: beside the output)");

    return {command, [options] {
        for (const std::string& path : {options->output, options->exr, options->statsJson, options->cameraOut})
            if (!path.empty()) checkOutputFolder(path);
        // Every flag is checked before the mesh is read (and logged about), so a bad one fails alone.
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        const core::Camera requested = options->view.camera();
        checkMethodFitsVolume(*options->view.renderOptions().method, volumeOptions);
        const core::SurfaceField field = core::loadSurface(options->mesh.source, options->mesh.load);
        render::RenderOptions renderOptions = options->view.renderOptions(field);

        const std::string folder = volumeCacheFolder(options->output, options->cacheDir);
        const std::string volumePath = defaultVolumePath(folder, options->mesh.source, volumeOptions.resolution);
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info);
        const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(field.mesh, volumeOptions, volumePath, &progress);
        const render::RenderScene scene(field, volume);
        const core::Camera camera = options->view.pictureCamera(scene, requested, *renderOptions.method,
                                                                renderOptions.width, renderOptions.height);
        const render::RenderResult result = render::renderImage(scene, camera, renderOptions, &progress);

        core::writePng(result.image, options->output, renderOptions.shading.transparentBackground);
        if (!options->exr.empty()) core::writeExr(result.image, result.layers, options->exr);
        const std::string cameraPath = options->cameraOut.empty() ? options->output + ".camera.json" : options->cameraOut;
        core::writeCameraJson(camera, cameraPath);

        const render::RenderStats& s = result.stats;
        if (s.nanPixels > 0)
            core::logWarning(std::to_string(s.nanPixels) + " pixels show NaN scalar values (drawn in magenta)");
        const glm::dvec2 angles = camera.angles();
        nlohmann::json stats = {{"seconds", s.seconds},
                                      {"width", renderOptions.width},
                                      {"height", renderOptions.height},
                                      {"samples_per_pixel", renderOptions.samplesPerPixel},
                                      {"pixels_direct", s.pixelsDirect},
                                      {"pixels_indirect", s.pixelsIndirect},
                                      {"pixels_background", s.pixelsBackground},
                                      {"rays_launched", s.raysLaunched},
                                      {"rays_landed", s.raysLanded},
                                      {"mean_steps", s.meanSteps()},
                                      {"nan_pixels", s.nanPixels},
                                      {"coherence", optimize::mappingCoherence(result.layers).value()},
                                      {"theta", angles.x},
                                      {"phi", angles.y},
                                      {"fov_y_deg", camera.fovYDeg},
                                      {"framed", options->view.framed()},
                                      {"volume_resolution", volume.options.resolution},
                                      {"volume_cache", volumePath},
                                      {"output", options->output},
                                      {"camera", cameraPath}};
        const nlohmann::json method = render::methodToJson(*renderOptions.method);
        for (const auto& [key, value] : method.items()) stats[key] = value;
        if (!options->statsJson.empty()) writeJsonFile(stats, options->statsJson);
        core::logInfo("wrote " + options->output + " (" + std::to_string(renderOptions.width) + "x" +
                      std::to_string(renderOptions.height) + ", " + renderOptions.method->name() +
                      ", " + options->view.describeFraming(camera) + ", " + std::to_string(s.seconds) +
                      " s render)");
    }};
}

}  // namespace ivis::app
