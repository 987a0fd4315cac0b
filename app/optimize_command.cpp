// `inversevis optimize MESH`: the best viewpoint and parameters of a method by simulated annealing;
// of a time series, one optimisation for all its steps (their mean scalar energy) and a frame per step.
#include "cli_checks.h"
#include "commands.h"
#include "json_output.h"
#include "mesh_options.h"
#include "output_files.h"
#include "optimization_options.h"
#include "series_render.h"
#include "series_survey.h"
#include "several_views.h"
#include "view_options.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/atomic_file.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/core/progress_bar.h>
#include <ivis/core/errors.h>
#include <ivis/optimize/annealing_plot.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/optimize/series_importance.h>
#include <ivis/render/method_json.h>
#include <ivis/vdb/volume_cache.h>

#include <memory>
#include <optional>

namespace ivis::app {

Command addOptimizeCommand(CLI::App& app)
{
    struct Options {
        MeshOptions mesh;
        ViewOptions view;
        OptimizationOptions optimization;
        int optResolution = 100;
        int views = 1;
        std::string output = "best.png";
        std::string json;
        std::string plot;
        std::string exr;
        std::string cameraOut;
        std::string viewOut;
        std::string cacheDir;
        std::vector<std::string> sources;
        double fps = 5;
        bool noVideo = false;
        std::vector<CLI::Option*> seriesFlags;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "optimize", "Find the best viewpoint and method parameters (simulated annealing); of a time series, one "
                    "view for all its steps");
    options->mesh.addTo(*command, &options->sources,
                        "one, or a time series of one geometry (a .pvd, several files, or one file with a --scalar "
                        "pattern), optimised once on the mean of its steps' energies");
    options->view.addTo(*command);
    options->optimization.addTo(*command);
    command->add_option("--opt-res", options->optResolution, "Optimisation resolution (rays per side)")
        ->check(optimizationResolutionRange())
        ->capture_default_str();
    command
        ->add_option("-o,--output", options->output,
                     "Picture of the best view at --res; of a series, a frame per step named as render names them "
                     "(out_0000.png, ...; out.mp4 when ffmpeg is on PATH)")
        ->capture_default_str();
    command
        ->add_option("--views", options->views,
                     "Several views: the best one and those of the visited views that show the most surface with it "
                     "(chosen greedily), their pictures side by side in -o with one colour bar and their union "
                     "visibility measured; each further view's view file is <output>.view<K>.json (visibility energy, one mesh)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    command->add_option("--json", options->json, "Result JSON: best view, parameters, energies, visited views");
    command->add_option("--plot", options->plot, "Picture of the visited camera positions (paper Fig. 6)");
    command->add_option("--exr", options->exr, "Multi-layer OpenEXR file of the best view (as render --exr)");
    command->add_option("--camera-out", options->cameraOut, "Camera JSON of the best view (default: <output>.camera.json)");
    command->add_option("--view-out", options->viewOut,
                        "View file of the best view: camera, method and optimised parameters, scalar, colour "
                        "(default: <output>.view.json; `render --view` reproduces the picture, the viewer loads it)");
    command->add_option("--cache-dir", options->cacheDir, kCacheDirHelp)->check(nonEmpty());
    options->seriesFlags = {
        command
            ->add_option("--fps", options->fps,
                         "Series: frames per second of the video, 0.1 to 240 (0.5 shows each step for 2 s)")
            ->check(finiteRange(0.1, 240.0))
            ->capture_default_str(),
        command->add_flag("--no-video", options->noVideo, "Series: no MP4 (by default one is made when ffmpeg is on PATH)")
            ->excludes("--fps")};

    return {command, [options] {
        options->view.viewIsStart = true;  // --view's angles start the search, whose views are framed
        std::vector<OutputFile> outputs = {
            {options->output, "-o", {".png"}},
            jsonOutput(options->json, "--json"),
            {options->plot, "--plot", {".png"}},
            {options->exr, "--exr", {".exr"}},
            jsonOutput(options->cameraOut.empty() ? options->output + ".camera.json" : options->cameraOut,
                       options->cameraOut.empty() ? "the camera file (-o's name + .camera.json)" : "--camera-out"),
            jsonOutput(options->viewOut.empty() ? options->output + ".view.json" : options->viewOut,
                       options->viewOut.empty() ? "the view file (-o's name + .view.json)" : "--view-out")};
        for (int k = 2; k <= options->views; ++k)
            outputs.push_back(jsonOutput(options->output + ".view" + std::to_string(k) + ".json",
                                         "a further view's view file (--views)"));
        const std::vector<InputFile> inputs = readFiles(options->sources, options->mesh.load.read.scalarFile,
                                                        options->view.cameraFile, options->view.viewFile);
        checkOutputFiles(outputs, inputs);
        options->view.showViewScalar(options->mesh, options->sources.front());
        options->mesh.fitReachTo({options->view.renderOptions().method});
        options->optimization.checkUsedBy({options->view.renderOptions().method}, {options->optResolution});
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        const core::Camera start = options->view.camera();
        if (start.orthographic)
            throw InputError("--ortho: the viewpoint optimisation places perspective cameras on the radius-2.5 sphere");
        // Without a camera given the annealing starts at the best of the six axis views.
        std::optional<glm::dvec2> startAngles;
        if (options->view.givesCamera()) startAngles = start.angles();
        const bool isSeries = core::isSeries(options->sources, options->mesh.load);
        if (!isSeries) rejectSeriesFlags(options->seriesFlags, options->sources.front());
        if (isSeries && options->views > 1)
            throw InputError(options->sources.front() + ": --views: a time series is shown from one view");
        if (options->views > 1 && optimize::parseEnergyKind(options->optimization.energy) != optimize::EnergyKind::Visibility)
            throw ValueError("--views chooses views by the surface they show together: it needs --energy visibility");
        // A series is optimised on the mean importance of its steps (optimize/series_importance.h),
        // measured with the importance range [0, 1]; the frames show its steps on their shared range.
        std::optional<core::SurfaceSeries> series;
        core::SurfaceField field;
        core::ColorScale seriesScale;
        if (isSeries) {
            series.emplace(options->sources, options->mesh.load);
            SeriesRenderRequest frames;  // the names renderSeries gives the frames
            frames.png = options->output;
            frames.exr = options->exr;
            frames.video = !options->noVideo;
            checkSeriesOutputFiles(frames, series->steps().size(), outputs, inputs);
            const SeriesSurvey survey = surveySeries(*series);
            options->view.checkColourFlags(survey.scalar, series->source());
            seriesScale = options->view.colorScaleRequest().resolve(survey.sample, series->source());
            // Silent, as the survey: the frames load the steps again and say their notes (a refused
            // series says only why).
            const core::ScopedLogLevel silent(core::LogLevel::Silent);
            field = optimize::meanImportanceField(*series, seriesScale.range);
        } else {
            options->mesh.source = options->sources.front();
            field = core::loadSurface(options->mesh.source, options->mesh.load);
        }
        render::RenderOptions renderOptions = options->view.renderOptions(field);
        const core::ScalarRange importanceRange = isSeries ? core::ScalarRange{0.0f, 1.0f} : renderOptions.shading.scale.range;
        const std::string source = isSeries ? series->source() : options->mesh.source;
        const std::string folder = vdb::optionalCacheFolder(options->cacheDir);
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info);
        progress.setContext(core::sourceStem(source));
        const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(
            field.mesh, volumeOptions, vdb::defaultVolumePath(folder, source, field.mesh, volumeOptions),
            &progress);
        const render::RenderScene scene(field, volume);

        const optimize::EnergyOptions energyOptions =
            options->optimization.energyOptions(options->optResolution, importanceRange);
        const optimize::EnergyEvaluator evaluator(scene, energyOptions);
        const auto ascentEvaluator =
            options->optimization.ascentEvaluator(scene, options->optResolution, importanceRange);
        const optimize::AnnealingResult result = optimize::annealViewpoint(
            evaluator, renderOptions.method,
            options->optimization.annealingOptions(startAngles,
                                                   options->view.framed() ? std::nullopt : std::optional(start.fovYDeg)),
            options->optimization.ascentOptions(), ascentEvaluator.get(), &progress,
            options->optimization.finalistEvaluator(scene, options->optResolution, importanceRange).get());
        const optimize::VisitedView& best = result.bestView();

        // The best view at display resolution, framed for the picture's size: picture, camera and energy.
        const core::Camera camera =
            options->view.pictureCamera(scene, best.camera, *best.method, renderOptions.width, renderOptions.height);
        renderOptions.method = best.method;
        const std::string cameraPath = options->cameraOut.empty() ? options->output + ".camera.json" : options->cameraOut;
        const std::string viewPath = options->viewOut.empty() ? options->output + ".view.json" : options->viewOut;
        nlohmann::json seriesStats, severalViews;
        double coherence = 0.0;
        const optimize::EnergyOptions displayOptions =
            options->optimization.measureOptions(renderOptions.height, importanceRange);
        optimize::EnergyOptions measureOptions = displayOptions;
        measureOptions.kind = optimize::EnergyKind::Visibility;
        measureOptions.paperLiteral = true;
        measureOptions.reveal = field.hasScalar();
        const optimize::EnergyEvaluator measure(scene, measureOptions);
        optimize::EnergyValue measured;
        nlohmann::json measures;  // measured's JSON, with the hot spots' shapes in the picture
        // Renamed into place together once all are written (a series' frames: by renderSeries).
        core::AtomicFileSet files;
        if (isSeries) {
            SeriesRenderRequest request;
            request.method = best.method;
            request.camera = best.camera;
            request.scale = seriesScale;
            request.volume = volumeOptions;
            request.cacheFolder = folder;
            request.png = options->output;
            request.exr = options->exr;
            request.cameraOut = cameraPath;
            request.video = !options->noVideo;
            request.fps = options->fps;
            seriesStats = renderSeries(*series, options->view, request, &progress);
            coherence = seriesStats.at("frames").at(0).at("coherence").get<double>();
            measured = measure.evaluate(camera, best.method);
            measures = measuresJson(measured, coherence, measureOptions.reveal);
            render::RenderOptions look = renderOptions;
            look.shading.scale = seriesScale;
            files.write(viewPath, [&](const std::string& temporary) {
                writeViewFile(viewOfPicture(core::readCameraJson(cameraPath), look, options->mesh.load, field.normalization),
                              temporary);
            });
        } else {
            const render::RenderResult picture = render::renderImage(scene, camera, renderOptions, &progress);
            if (options->views > 1) {
                const SeveralViews set = renderSeveralViews(
                    scene, result, evaluator, measure, options->optimization.annealingOptions(startAngles, std::nullopt),
                    options->view.framed(), renderOptions, camera, picture, options->views);
                files.write(options->output, [&](const std::string& temporary) {
                    core::writePng(set.figure, temporary, renderOptions.shading.transparentBackground);
                });
                for (std::size_t k = 1; k < set.views.size(); ++k) {
                    render::RenderOptions look = renderOptions;
                    look.method = set.views[k].method;
                    files.write(options->output + ".view" + std::to_string(k + 1) + ".json", [&](const std::string& temporary) {
                        writeViewFile(viewOfPicture(set.views[k].camera, look, options->mesh.load, field.normalization), temporary);
                    });
                }
                severalViews = set.json;
                core::logInfo(set.line);
            } else {
                files.write(options->output, [&](const std::string& temporary) {
                    core::writePng(picture.figure, temporary, renderOptions.shading.transparentBackground);
                });
            }
            if (!options->exr.empty())
                files.write(options->exr, [&](const std::string& temporary) {
                    core::writeExr(picture.image, picture.layers, temporary, field.normalization);
                });
            files.write(cameraPath, [&](const std::string& temporary) {
                core::writeCameraJson(camera, temporary, field.normalization);
            });
            files.write(viewPath, [&](const std::string& temporary) {
                writeViewFile(viewOfPicture(camera, renderOptions, options->mesh.load, field.normalization), temporary);
            });
            coherence = optimize::mappingCoherence(picture.layers).value();
            measured = optimize::measurePicture(measure, picture.layers);  // the picture's own pixels
            measures = measuresJson(measured, coherence, measureOptions.reveal);
            addHotSpotShapes(measures, measure, picture.layers);
        }
        // The visibility energy is the measure itself: measure it once.
        const optimize::EnergyValue display =
            displayOptions.kind == optimize::EnergyKind::Visibility
                ? measured
                : optimize::EnergyEvaluator(scene, displayOptions).evaluate(camera, best.method);
        if (!options->plot.empty())
            files.write(options->plot, [&](const std::string& temporary) {
                core::writePng(optimize::plotVisitedViews(result), temporary, false);
            });

        nlohmann::json visited = nlohmann::json::array();
        for (const auto& view : result.visited) visited.push_back(visitedViewJson(view));
        nlohmann::json json = {
            {"mesh", source},
            {"energy", optimize::toString(energyOptions.kind)},
            {"opt_res", options->optResolution},
            {"ascent_res", ascentEvaluator ? options->optimization.ascentResolution : options->optResolution},
            {"alpha_scan", options->optimization.alphaScan},
            {"display_res", renderOptions.height},
            {"seed", options->optimization.seed},
            {"seconds", result.seconds},
            {"evaluations", result.evaluations},
            {"theta", best.thetaDeg},
            {"phi", best.phiDeg},
            {"fov_y_deg", camera.fovYDeg},
            {"framed", options->view.framed()},
            {"camera", cameraPath},
            {"view", viewPath},
            {"params", render::methodToJson(*best.method)},
            {"energy_value", best.value.energy},
            {"front_energy_value", best.value.front},
            {"display_energy_value", display.energy},
            {"display_front_energy_value", display.front},
            {"mean_importance", best.value.meanImportance},
            {"measures", measures},
            {"output", options->output},
            {"visited", visited}};
        if (isSeries) json["series"] = seriesStats;
        if (!severalViews.is_null()) json["several_views"] = severalViews;
        if (result.hotSpots) {
            json["hot_spot_rule"] = optimize::hotSpotChoiceJson(*result.hotSpots);
            core::logInfo(hotSpotChoiceLine(*result.hotSpots));
        }
        if (result.readable) {
            json["readable_rule"] = readableSettingJson(*result.readable);
            core::logInfo(readableSettingLine(*result.readable));
        }
        if (!options->json.empty())
            files.write(options->json, [&](const std::string& temporary) { writeJsonFile(json, temporary); });
        files.commit();
        core::logInfo(best.method->name() + ": best view theta " +
                      std::to_string(best.thetaDeg) + " phi " + std::to_string(best.phiDeg) + ", " +
                      optimize::toString(energyOptions.kind) + " " + std::to_string(display.energy) + " (front " +
                      std::to_string(display.front) + ") at " + std::to_string(renderOptions.height) +
                      " rays per side, " + options->view.describeFraming(camera) + ", " +
                      std::to_string(result.seconds) + " s");
    }};
}

}  // namespace ivis::app
