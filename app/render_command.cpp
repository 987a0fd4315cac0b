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
#include <ivis/optimize/readable_rule.h>
#include <ivis/render/method_json.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/volume_cache.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <memory>
#include <optional>

namespace ivis::app {

namespace {

/// What `render` was given on its command line.
struct RenderFlags {
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

/// What every picture of one `render` run shares, checked before anything is read.
struct RenderPlan {
    std::vector<OutputFile> outputs;
    std::vector<InputFile> inputs;
    render::RenderOptions asked;        ///< the method and the picture's size (before the data's scale)
    bool chooseRule = false;            ///< the readable rule is chosen (optimize/readable_rule.h)
    SeriesRenderRequest frameRange;     ///< --frames
    std::vector<glm::ivec2> probePixels;
    vdb::VolumeOptions volumeOptions;
    core::Camera requested;             ///< the camera asked for (framed later when the view is)
};

/// `render SERIES`: a picture per step of @a flags' series (and a video, the stats, the view).
void renderSeriesPictures(RenderFlags& flags, const RenderPlan& plan, core::ProgressBar& progress)
{
    if (!flags.tearMap.empty())
        throw InputError("--tear-map: a series has one picture per step; render the step alone");
    if (!flags.unseenMap.empty())
        throw InputError("--unseen-map: a series has one picture per step; render the step alone");
    if (!flags.probes.empty())
        throw InputError("--probe: a series has one picture per step; render the step alone");
    core::SurfaceSeries series(flags.sources, flags.mesh.load);
    SeriesRenderRequest request;
    request.png = flags.output;
    request.exr = flags.exr;
    request.video = !flags.noVideo && flags.frames.empty();  // a job's part: no video
    request.firstStep = plan.frameRange.firstStep;
    request.lastStep = plan.frameRange.lastStep;
    if (flags.legendOnly.empty()) checkSeriesOutputFiles(request, series.steps().size(), plan.outputs, plan.inputs);
    request.method = plan.asked.method;
    request.camera = plan.requested;
    // Loads every step: a bad one fails before anything is written.
    const core::ColorScaleRequest eachFrame = flags.view.colorScaleRequest();
    const SeriesSurvey survey = surveySeries(series, flags.rangePerFrame ? &eachFrame : nullptr);
    flags.view.checkColourFlags(survey.scalar, series.source());
    if (!flags.legendOnly.empty() && !survey.scalar)
        throw InputError(series.source() + ": no scalar to draw a colour bar of (see --scalar)");
    request.stepScales = survey.stepScales;
    if (!flags.rangePerFrame || !flags.legendOnly.empty())
        request.scale = flags.view.colorScaleRequest().resolve(survey.sample, series.source());
    if (!flags.legendOnly.empty()) {
        render::RenderOptions legend = plan.asked;
        legend.shading.scale = *request.scale;
        legend.scalarName = series.load(0).name;
        writeLegendFile(flags.legendOnly, legend);
        return;
    }
    request.volume = plan.volumeOptions;
    request.cacheFolder = vdb::optionalCacheFolder(flags.cacheDir);  // after the checks: their one line
    request.cameraOut = flags.cameraOut;
    request.fps = flags.fps;
    request.measure = flags.measure;
    request.minCoherence = plan.chooseRule ? flags.minCoherence : 0.0;
    const nlohmann::json stats = renderSeries(series, flags.view, request, &progress);
    if (!flags.viewOut.empty()) {
        render::RenderOptions look = plan.asked;
        look.shading.scale = request.scale.value_or(look.shading.scale);
        look.method = request.method;
        writeViewFile(viewOfPicture(core::readCameraJson(stats.at("camera").get<std::string>()), look,
                                    flags.mesh.load, series.load(0).normalization),
                      flags.viewOut);
    }
    if (!flags.statsJson.empty()) writeJsonFile(stats, flags.statsJson);
}

/// `render MESH`: the picture, its layers, camera, view, stats, measures and probes.
void renderOnePicture(RenderFlags& flags, const RenderPlan& plan, core::ProgressBar& progress)
{
    flags.mesh.source = flags.sources.front();
    const core::SurfaceField field = core::loadSurface(flags.mesh.source, flags.mesh.load);
    render::RenderOptions renderOptions = flags.view.renderOptions(field);
    if (!flags.legendOnly.empty()) {
        if (!field.hasScalar())
            throw InputError(flags.mesh.source + ": no scalar to draw a colour bar of (see --scalar)");
        writeLegendFile(flags.legendOnly, renderOptions);
        return;
    }

    const std::string volumePath =
        vdb::defaultVolumePath(vdb::optionalCacheFolder(flags.cacheDir), flags.mesh.source, field.mesh, plan.volumeOptions);
    vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(field.mesh, plan.volumeOptions, volumePath, &progress);
    const render::RenderScene scene(field, volume);
    volume.releaseSampledGrids();  // the scene holds its own copies of what it samples
    optimize::PictureRequest pictureRequest;
    pictureRequest.options = renderOptions;
    pictureRequest.camera = plan.requested;
    pictureRequest.framed = flags.view.framed();
    pictureRequest.minCoherence = plan.chooseRule ? flags.minCoherence : 0.0;
    const optimize::Picture picture = optimize::makePicture(scene, pictureRequest, &progress);
    if (picture.readable) core::logInfo(readableSettingLine(*picture.readable));
    const std::optional<optimize::ReadableSetting>& readable = picture.readable;
    const core::Camera& camera = picture.camera;
    renderOptions.method = picture.method;
    const render::RenderResult& result = picture.result;

    // Every output under a temporary name, renamed into place together once all are written.
    core::AtomicFileSet files;
    files.write(flags.output, [&](const std::string& temporary) {
        core::writePng(result.figure, temporary, renderOptions.shading.transparentBackground);
    });
    if (!flags.exr.empty())
        files.write(flags.exr, [&](const std::string& temporary) {
            core::writeExr(result.image, result.layers, temporary, field.normalization);
        });
    const std::string cameraPath = flags.cameraOut.empty() ? flags.output + ".camera.json" : flags.cameraOut;
    files.write(cameraPath, [&](const std::string& temporary) {
        core::writeCameraJson(camera, temporary, field.normalization);
    });
    if (!flags.viewOut.empty())
        files.write(flags.viewOut, [&](const std::string& temporary) {
            writeViewFile(viewOfPicture(camera, renderOptions, flags.mesh.load, field.normalization), temporary);
        });

    const render::RenderStats& s = result.stats;
    if (s.nanPixels > 0)
        core::logWarning(std::to_string(s.nanPixels) + " pixels show NaN scalar values (drawn in magenta)");
    const glm::dvec2 angles = camera.angles();
    std::vector<char> torn;  // marked only for a tear map
    const double coherence =
        optimize::mappingCoherence(result.layers, optimize::kCoherenceDistance, flags.tearMap.empty() ? nullptr : &torn)
            .value();
    if (!flags.tearMap.empty())
        files.write(flags.tearMap, [&](const std::string& temporary) {
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
                                  {"framed", flags.view.framed()},
                                  {"volume_resolution", volume.options.resolution},
                                  {"volume_cache",  // null: no cache folder could be written
                                   volumePath.empty() ? nlohmann::json() : nlohmann::json(volumePath)},
                                  {"output", flags.output},
                                  {"camera", cameraPath}};
    const nlohmann::json method = render::methodToJson(*renderOptions.method);
    for (const auto& [key, value] : method.items()) stats[key] = value;
    if (readable) stats["readable_rule"] = readableSettingJson(*readable);
    if (flags.measure || !flags.unseenMap.empty()) {
        core::Image unseen;
        stats["measures"] = pictureMeasuresJson(scene, camera, renderOptions.method, renderOptions.height,
                                                renderOptions.shading.scale.range, coherence, result.layers,
                                                flags.unseenMap.empty() ? nullptr : &unseen);
        core::logInfo(measuresLine(stats["measures"]));
        if (!flags.unseenMap.empty())
            files.write(flags.unseenMap,
                        [&](const std::string& temporary) { core::writePng(unseen, temporary, false); });
    }
    std::string probeLines;  // said once the plan.outputs are in place
    for (const glm::ivec2& pixel : plan.probePixels) {
        const ProbeReport report =
            probeReport(scene, renderOptions.method, camera, renderOptions.width, renderOptions.height, pixel,
                        renderOptions.adaptive);
        stats["probes"].push_back(probeJson(report, field));
        probeLines += probeLine(report, field) + "\n";
    }
    if (!flags.statsJson.empty())
        files.write(flags.statsJson, [&](const std::string& temporary) { writeJsonFile(stats, temporary); });
    files.commit();
    std::fputs(probeLines.c_str(), stdout);
    core::logInfo("wrote " + flags.output + " (" + std::to_string(renderOptions.width) + "x" +
                  std::to_string(renderOptions.height) + ", " + renderOptions.method->name() +
                  ", " + flags.view.describeFraming(camera) + ", " + std::to_string(s.seconds) +
                  " s render)");
}

}  // namespace

Command addRenderCommand(CLI::App& app)
{
    auto options = std::make_shared<RenderFlags>();
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
    for (const char* output : {"--output", "--exr", "--stats-json", "--measure", "--tear-map", "--unseen-map",
                               "--camera-out", "--view-out"})
        legendOnly->excludes(command->get_option(output));
    legendOnly->excludes(probe);
    // Nor does the bar depend on the view or how rays are traced (these were accepted and ignored).
    for (const char* unused : {"--no-legend", "--theta", "--phi", "--fov", "--ortho", "--camera", "--method", "--spp",
                               "--full-trace"})
        if (CLI::Option* option = command->get_option_no_throw(unused)) legendOnly->excludes(option);
    command->add_option("--cache-dir", options->cacheDir, kCacheDirHelp)->check(nonEmpty());
    options->seriesFlags = {
        command->add_flag("--range-per-frame", options->rangePerFrame,
                          "Series: each frame's colour range is its own step's data range (default: one range over "
                          "all steps)")
            ->excludes("--range"),
        command->add_option("--frames", options->frames,
                            "Series: render only steps FIRST:LAST (from 0, inclusive), numbered as in the whole series: "
                            "one job of a render spread over a cluster (needs a fixed view: --view, --camera or --fov; "
                            "no video; a LAST past the series' end stops at its last step)"),
        command
            ->add_option("--fps", options->fps,
                         "Series: frames per second of the video, 0.1 to 240 (0.5 shows each step for 2 s)")
            ->check(finiteRange(0.1, 240.0))
            ->capture_default_str()
            ->excludes("--frames"),  // a job's part makes no video
        command->add_flag("--no-video", options->noVideo,
                          "Series: no MP4 (by default one is made when ffmpeg is on PATH)")
            ->excludes("--fps")};
    legendOnly->excludes("--range-per-frame");  // the bar alone has one scale: the series' (no frame's own)
    // A view file holds one colour range (it was written as [0, 1], which no frame had).
    command->get_option("--range-per-frame")->excludes("--view-out");

    return {command, [options, command] {
        options->view.rangeOfEachPicture = options->rangePerFrame;
        // The camera is written beside the picture (a series': beside its frames) unless told where.
        const bool defaultCamera = options->cameraOut.empty();
        RenderPlan plan;
        plan.outputs = {
            {options->output, "-o", {".png"}},
            {options->exr, "--exr", {".exr"}},
            jsonOutput(options->statsJson, "--stats-json"),
            jsonOutput(defaultCamera ? options->output + ".camera.json" : options->cameraOut,
                       defaultCamera ? "the camera file (-o's name + .camera.json)" : "--camera-out"),
            {options->legendOnly, "--legend-only", {".svg", ".png"}},
            jsonOutput(options->viewOut, "--view-out"),
            {options->tearMap, "--tear-map", {".png"}},
            {options->unseenMap, "--unseen-map", {".png"}}};
        plan.inputs = readFiles(options->sources, options->mesh.load.read.scalarFile, options->view.cameraFile,
                                options->view.viewFile);
        checkOutputFiles(plan.outputs, plan.inputs);
        plan.asked = options->view.renderOptions();
        // The readable rule is chosen when the method has one and neither an option nor --view gives it.
        const std::string readableRuleKey = plan.asked.method->info().readableRuleParameter;
        if (readableRuleKey.empty() && command->get_option("--min-coherence")->count() > 0)
            throw ValueError("--min-coherence: " + plan.asked.method->name() +
                             " has no rule for drawing rays to loosen (inversevis-wrap: --stable-shift)");
        plan.chooseRule =
            options->minCoherence > 0.0 && !readableRuleKey.empty() && !options->view.givesParameter(readableRuleKey);
        options->view.showViewScalar(options->mesh, options->sources.front());
        const bool isSeries = core::isSeries(options->sources, options->mesh.load);
        if (!isSeries) rejectSeriesFlags(options->seriesFlags, options->sources.front());
        if (!options->frames.empty()) {
            parseFrameRange(options->frames, plan.frameRange);
            if (options->view.framed())
                throw InputError("--frames: every job must use one camera; give --view, --camera or --fov (a framed "
                                 "view follows the job's first step)");
        }
        for (const std::string& text : options->probes)
            plan.probePixels.push_back(parseProbePixel(text, plan.asked.width, plan.asked.height));
        // Every flag is checked before the mesh is read (and logged about), so a bad one fails alone.
        options->mesh.fitReachTo({plan.asked.method});
        plan.volumeOptions = options->mesh.volumeOptions();
        plan.requested = options->view.camera();
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info);
        progress.setContext(core::sourceStem(options->sources.front()));
        if (isSeries) renderSeriesPictures(*options, plan, progress);
        else renderOnePicture(*options, plan, progress);
    }};
}

}  // namespace ivis::app
