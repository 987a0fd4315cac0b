// `inversevis render MESH`: one picture of a method, with optional EXR layers, stats and camera;
// `inversevis render SERIES`: one such picture per step of a time series, and a video.
#include "cli_checks.h"
#include "commands.h"
#include "json_output.h"
#include "legend_file.h"
#include "mesh_options.h"
#include "output_files.h"
#include "probe_report.h"
#include "series_render.h"
#include "series_survey.h"
#include "view_options.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/core/progress_bar.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/picture.h>
#include <ivis/optimize/readability.h>
#include <ivis/render/method_json.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/volume_cache.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <optional>

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
        std::string legendOnly;
        std::string viewOut;
        std::string tearMap;
        std::string unseenMap;
        std::vector<std::string> probes;
        std::string cacheDir;
        std::vector<std::string> sources;
        bool rangePerFrame = false;
        std::string frames;
        double fps = 5;
        bool noVideo = false;
        bool measure = false;
        double minCoherence = optimize::kDefaultMinCoherence;
        std::vector<CLI::Option*> seriesFlags;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a method's picture to PNG (and EXR layers); of a time series, one picture per step");
    options->mesh.addTo(*command, &options->sources,
                        "one, or a time series: a .pvd, several files (one step each), or one file with a "
                        "--scalar pattern such as 'pressure_t*' (one step per matching array, in natural order)");
    options->view.addTo(*command);
    command
        ->add_option("-o,--output", options->output,
                     "PNG file; of a series, step k's frame is the name with _ and k in 4 digits (more past 9999 "
                     "steps) before the extension (out.png: out_0000.png, out_0001.png, ...) and the video is out.mp4")
        ->capture_default_str();
    command->add_option("--exr", options->exr,
                        "Multi-layer OpenEXR file (linear colour + per-pixel layers); of a series, numbered as the PNGs");
    command->add_option("--stats-json", options->statsJson, "Write render statistics as JSON (of a series: per frame too)");
    command->add_flag("--measure", options->measure,
                      "Also measure what the picture shows (docs/measures.md: surface visibility on the 200^3 grid, "
                      "paper-literal, front-only, with a scalar the hot-spot reveal) into --stats-json and the log; "
                      "traces the method again with the picture's height in rays per side");
    command
        ->add_option("--min-coherence", options->minCoherence,
                     "Readable rule: when the method's rule for drawing rays (inversevis-wrap: --stable-shift) is "
                     "given neither as an option nor by --view, the loosest rule (from an eighth of the default to "
                     "8 times it) whose picture keeps an estimated mapping coherence of at least this, judged on the "
                     "view's picture at 1000 rows (the measure's size) whatever --res (beyond the paper; a series: "
                     "chosen on its first step); 0: the default rule")
        ->check(finiteRange(0.0, 1.0))
        ->capture_default_str();
    command->add_option("--tear-map", options->tearMap,
                        "Also write a PNG of the picture in grey with its tears in red: the indirect pixels whose "
                        "neighbour's surface point lies further than the coherence measure's 0.1 (one picture only)");
    command->add_option("--unseen-map", options->unseenMap,
                        "Also write a PNG of the surface seen from the picture's side and from the opposite side, red "
                        "where no pixel of the picture shows it (the surface voxels --measure counts as unseen; "
                        "measures the picture; one picture only)");
    auto* probe = command->add_option(
        "--probe", options->probes,
        "What pixel X,Y of the picture (from its top left, the colour bar's margin not counted) shows, printed on "
        "stdout and into --stats-json's probes: background, direct or indirect, the surface point in the mesh's "
        "units, its file cell, the scalar there, and a --theta/--phi that shows the point directly (repeatable; one "
        "picture only)")
        ->allow_extra_args(false);  // one X,Y per --probe: the mesh after it is not taken for a pixel
    command->add_option("--camera-out", options->cameraOut, "Camera JSON written (default: <output>.camera.json)");
    command->add_option("--view-out", options->viewOut,
                        "Write the picture's view file (camera, method and parameters, scalar, colour; `render --view` "
                        "and the viewer read it)");
    auto* legendOnly = command->add_option("--legend-only", options->legendOnly,
                                           "Write only the colour bar, to FILE.svg (vector) or FILE.png, sized as "
                                           "beside a --res picture (of a series: its one colour scale)");
    // Nothing else is written beside the bar alone (these were accepted, and nothing written).
    for (const char* output : {"--exr", "--stats-json", "--measure", "--tear-map", "--unseen-map", "--camera-out",
                               "--view-out"})
        legendOnly->excludes(command->get_option(output));
    legendOnly->excludes(probe);
    command->add_option("--cache-dir", options->cacheDir, kCacheDirHelp);
    options->seriesFlags = {
        command->add_flag("--range-per-frame", options->rangePerFrame,
                          "Series: each frame's colour range is its own step's data range (default: one range over "
                          "all steps)")
            ->excludes("--range"),
        command->add_option("--frames", options->frames,
                            "Series: render only steps FIRST:LAST (from 0, inclusive), numbered as in the whole series: "
                            "one job of a render spread over a cluster (needs a fixed view: --view, --camera or --fov; "
                            "no video)"),
        command
            ->add_option("--fps", options->fps,
                         "Series: frames per second of the video, 0.1 to 240 (0.5 shows each step for 2 s)")
            ->check(finiteRange(0.1, 240.0))
            ->capture_default_str()
            ->excludes("--frames"),  // a job's part makes no video
        command->add_flag("--no-video", options->noVideo,
                          "Series: no MP4 (by default one is made when ffmpeg is on PATH)")
            ->excludes("--fps")};

    return {command, [options, command] {
        options->view.rangeOfEachPicture = options->rangePerFrame;
        // The camera is written beside the picture (a series': beside its frames) unless told where.
        const bool defaultCamera = options->cameraOut.empty();
        const std::vector<OutputFile> outputs = {
            {options->output, "-o", {".png"}},
            {options->exr, "--exr", {".exr"}},
            {options->statsJson, "--stats-json", {}},
            {defaultCamera ? options->output + ".camera.json" : options->cameraOut,
             defaultCamera ? "the camera file (-o's name + .camera.json)" : "--camera-out", {}},
            {options->legendOnly, "--legend-only", {".svg", ".png"}},
            {options->viewOut, "--view-out", {}},
            {options->tearMap, "--tear-map", {".png"}},
            {options->unseenMap, "--unseen-map", {".png"}}};
        const std::vector<InputFile> inputs = readFiles(options->sources, options->mesh.load.read.scalarFile,
                                                        options->view.cameraFile, options->view.viewFile);
        checkOutputFiles(outputs, inputs);
        const render::RenderOptions asked = options->view.renderOptions();  // the method and the picture's size
        // The readable rule is chosen when the method has one and neither an option nor --view gives it.
        const std::string readabilityKey = asked.method->info().readabilityParameter;
        if (readabilityKey.empty() && command->get_option("--min-coherence")->count() > 0)
            throw ValueError("--min-coherence: " + asked.method->name() +
                             " has no rule for drawing rays to loosen (inversevis-wrap: --stable-shift)");
        const bool chooseRule =
            options->minCoherence > 0.0 && !readabilityKey.empty() && !options->view.givesParameter(readabilityKey);
        if (const ViewFile* view = options->view.view())
            options->mesh.useViewScalar(view->scalar, view->scalarFile, view->cellToPoint, view->hotSpots);
        const bool isSeries = core::isSeries(options->sources, options->mesh.load);
        if (!isSeries) rejectSeriesFlags(options->seriesFlags, options->sources.front());
        SeriesRenderRequest frameRange;  // --frames, checked before anything is read
        if (!options->frames.empty()) {
            parseFrameRange(options->frames, frameRange);
            if (options->view.framed())
                throw InputError("--frames: every job must use one camera; give --view, --camera or --fov (a framed "
                                 "view follows the job's first step)");
        }
        std::vector<glm::ivec2> probePixels;
        for (const std::string& text : options->probes)
            probePixels.push_back(parseProbePixel(text, asked.width, asked.height));
        // Every flag is checked before the mesh is read (and logged about), so a bad one fails alone.
        options->mesh.fitReachTo({asked.method});
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        const core::Camera requested = options->view.camera();
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info);
        progress.setContext(core::sourceStem(options->sources.front()));
        if (isSeries) {
            if (!options->tearMap.empty())
                throw InputError("--tear-map: a series has one picture per step; render the step alone");
            if (!options->unseenMap.empty())
                throw InputError("--unseen-map: a series has one picture per step; render the step alone");
            if (!options->probes.empty())
                throw InputError("--probe: a series has one picture per step; render the step alone");
            core::SurfaceSeries series(options->sources, options->mesh.load);
            SeriesRenderRequest request;
            request.png = options->output;
            request.exr = options->exr;
            request.video = !options->noVideo && options->frames.empty();  // a job's part: no video
            request.firstStep = frameRange.firstStep;
            request.lastStep = frameRange.lastStep;
            if (options->legendOnly.empty()) checkSeriesOutputFiles(request, series.steps().size(), outputs, inputs);
            request.method = options->view.renderOptions().method;
            request.camera = requested;
            // Loads every step: a bad one fails before anything is written.
            const core::ColorScaleRequest eachFrame = options->view.colorScaleRequest();
            const SeriesSurvey survey = surveySeries(series, options->rangePerFrame ? &eachFrame : nullptr);
            options->view.checkColourFlags(survey.scalar, series.source());
            if (!options->legendOnly.empty() && !survey.scalar)
                throw InputError(series.source() + ": no scalar to draw a colour bar of (see --scalar)");
            request.stepScales = survey.stepScales;
            if (!options->rangePerFrame || !options->legendOnly.empty())
                request.scale = options->view.colorScaleRequest().resolve(survey.sample);
            if (!options->legendOnly.empty()) {
                render::RenderOptions legend = options->view.renderOptions();
                legend.shading.scale = *request.scale;
                legend.scalarName = series.load(0).name;
                writeLegendFile(options->legendOnly, legend);
                return;
            }
            request.volume = volumeOptions;
            request.cacheFolder = vdb::optionalCacheFolder(options->cacheDir);  // after the checks: their one line
            request.cameraOut = options->cameraOut;
            request.fps = options->fps;
            request.measure = options->measure;
            request.minCoherence = chooseRule ? options->minCoherence : 0.0;
            const nlohmann::json stats = renderSeries(series, options->view, request, &progress);
            if (!options->viewOut.empty()) {
                render::RenderOptions look = options->view.renderOptions();
                look.shading.scale = request.scale.value_or(look.shading.scale);
                look.method = request.method;
                writeViewFile(viewOfPicture(core::readCameraJson(stats.at("camera").get<std::string>()), look,
                                            options->mesh.load, series.load(0).normalization),
                              options->viewOut);
            }
            if (!options->statsJson.empty()) writeJsonFile(stats, options->statsJson);
            return;
        }
        options->mesh.source = options->sources.front();
        const core::SurfaceField field = core::loadSurface(options->mesh.source, options->mesh.load);
        render::RenderOptions renderOptions = options->view.renderOptions(field);
        if (!options->legendOnly.empty()) {
            if (!field.hasScalar())
                throw InputError(options->mesh.source + ": no scalar to draw a colour bar of (see --scalar)");
            writeLegendFile(options->legendOnly, renderOptions);
            return;
        }

        const std::string volumePath =
            vdb::defaultVolumePath(vdb::optionalCacheFolder(options->cacheDir), options->mesh.source, field.mesh, volumeOptions);
        const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(field.mesh, volumeOptions, volumePath, &progress);
        const render::RenderScene scene(field, volume);
        optimize::PictureRequest pictureRequest;
        pictureRequest.options = renderOptions;
        pictureRequest.camera = requested;
        pictureRequest.framed = options->view.framed();
        pictureRequest.minCoherence = chooseRule ? options->minCoherence : 0.0;
        const optimize::Picture picture = optimize::makePicture(scene, pictureRequest, &progress);
        if (picture.readable) core::logInfo(readableSettingLine(*picture.readable));
        const std::optional<optimize::ReadableSetting>& readable = picture.readable;
        const core::Camera& camera = picture.camera;
        renderOptions.method = picture.method;
        const render::RenderResult& result = picture.result;

        // Every output under a temporary name, renamed into place together once all are written.
        core::AtomicFileSet files;
        files.write(options->output, [&](const std::string& temporary) {
            core::writePng(result.figure, temporary, renderOptions.shading.transparentBackground);
        });
        if (!options->exr.empty())
            files.write(options->exr, [&](const std::string& temporary) {
                core::writeExr(result.image, result.layers, temporary, field.normalization);
            });
        const std::string cameraPath = options->cameraOut.empty() ? options->output + ".camera.json" : options->cameraOut;
        files.write(cameraPath, [&](const std::string& temporary) {
            core::writeCameraJson(camera, temporary, field.normalization);
        });
        if (!options->viewOut.empty())
            files.write(options->viewOut, [&](const std::string& temporary) {
                writeViewFile(viewOfPicture(camera, renderOptions, options->mesh.load, field.normalization), temporary);
            });

        const render::RenderStats& s = result.stats;
        if (s.nanPixels > 0)
            core::logWarning(std::to_string(s.nanPixels) + " pixels show NaN scalar values (drawn in magenta)");
        const glm::dvec2 angles = camera.angles();
        std::vector<char> torn;  // marked only for a tear map
        const double coherence =
            optimize::mappingCoherence(result.layers, optimize::kCoherenceDistance, options->tearMap.empty() ? nullptr : &torn)
                .value();
        if (!options->tearMap.empty())
            files.write(options->tearMap, [&](const std::string& temporary) {
                core::writePng(optimize::tearMap(result.image, torn), temporary, false);
            });
        nlohmann::json stats = {{"seconds", s.seconds},
                                      {"width", renderOptions.width},
                                      {"height", renderOptions.height},
                                      {"samples_per_pixel", renderOptions.samplesPerPixel},
                                      {"pixels_direct", s.pixelsDirect},
                                      {"pixels_indirect", s.pixelsIndirect},
                                      {"pixels_background", s.pixelsBackground},
                                      {"seeds_interpolated", s.seedsInterpolated},
                                      {"pixels_skipped", s.pixelsSkipped},
                                      {"full_trace", !renderOptions.adaptive.enabled},
                                      {"rays_launched", s.raysLaunched},
                                      {"rays_landed", s.raysLanded},
                                      {"mean_steps", s.meanSteps()},
                                      {"nan_pixels", s.nanPixels},
                                      {"coherence", coherence},
                                      {"theta", angles.x},
                                      {"phi", angles.y},
                                      {"fov_y_deg", camera.fovYDeg},
                                      {"framed", options->view.framed()},
                                      {"volume_resolution", volume.options.resolution},
                                      {"volume_cache",  // null: no cache folder could be written
                                       volumePath.empty() ? nlohmann::json() : nlohmann::json(volumePath)},
                                      {"output", options->output},
                                      {"camera", cameraPath}};
        const nlohmann::json method = render::methodToJson(*renderOptions.method);
        for (const auto& [key, value] : method.items()) stats[key] = value;
        if (readable) stats["readability"] = readableSettingJson(*readable);
        if (options->measure || !options->unseenMap.empty()) {
            core::Image unseen;
            stats["measures"] = pictureMeasuresJson(scene, camera, renderOptions.method, renderOptions.height,
                                                    renderOptions.shading.scale.range, coherence,
                                                    options->unseenMap.empty() ? nullptr : &unseen);
            core::logInfo(measuresLine(stats["measures"]));
            if (!options->unseenMap.empty())
                files.write(options->unseenMap,
                            [&](const std::string& temporary) { core::writePng(unseen, temporary, false); });
        }
        std::string probeLines;  // said once the outputs are in place
        for (const glm::ivec2& pixel : probePixels) {
            const ProbeReport report =
                probeReport(scene, renderOptions.method, camera, renderOptions.width, renderOptions.height, pixel,
                            renderOptions.adaptive);
            stats["probes"].push_back(probeJson(report, field));
            probeLines += probeLine(report, field) + "\n";
        }
        if (!options->statsJson.empty())
            files.write(options->statsJson, [&](const std::string& temporary) { writeJsonFile(stats, temporary); });
        files.commit();
        std::fputs(probeLines.c_str(), stdout);
        core::logInfo("wrote " + options->output + " (" + std::to_string(renderOptions.width) + "x" +
                      std::to_string(renderOptions.height) + ", " + renderOptions.method->name() +
                      ", " + options->view.describeFraming(camera) + ", " + std::to_string(s.seconds) +
                      " s render)");
    }};
}

}  // namespace ivis::app
