// `inversevis evaluate MESH...`: the paper's Table 1 with the measures (docs/measures.md) at each method's best
// view (surface visibility with its front-only part, paper-literal visibility, mapping coherence and,
// with a scalar, hot-spot reveal) and Table 2 (viewpoint optimisation seconds per resolution).
#include "cli_checks.h"
#include "commands.h"
#include "json_output.h"
#include "mesh_options.h"
#include "output_files.h"
#include "method_options.h"
#include "evaluation_report.h"
#include "optimization_options.h"
#include "several_views.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/content_hash.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/core/progress_bar.h>
#include <ivis/core/surface_source.h>
#include <ivis/optimize/coherence.h>
#include <ivis/render/method_json.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/volume_cache.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace ivis::app {
namespace {

/// The mesh-and-method pairs of --only ("STEM:METHOD"), checked against the meshes and methods of
/// the command line; empty when --only was not given (every pair).
std::vector<std::pair<std::string, std::string>> onlyPairs(const std::vector<std::string>& only,
                                                           const std::vector<std::string>& meshes,
                                                           const std::vector<std::string>& methods)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const std::string& text : only) {
        const std::size_t colon = text.rfind(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
            throw InputError("--only '" + text + "': expected MESH:METHOD (the mesh's file stem, e.g. armadillo:mirror)");
        const std::string stem = text.substr(0, colon), method = text.substr(colon + 1);
        if (std::none_of(meshes.begin(), meshes.end(), [&](const std::string& m) { return core::sourceStem(m) == stem; }))
            throw InputError("--only '" + text + "': no mesh '" + stem + "' among the meshes given");
        if (std::find(methods.begin(), methods.end(), method) == methods.end())
            throw InputError("--only '" + text + "': method '" + method + "' is not among --methods");
        pairs.emplace_back(stem, method);
    }
    return pairs;
}

/// @a settings without the flags @a method does not use, so that an entry of a job of that method
/// alone (given only the flags it uses: OptimizationOptions::checkUsedBy) equals one of a run of all.
nlohmann::json settingsUsedBy(nlohmann::json settings, const render::MethodInfo& method)
{
    if (method.scannedParameter.empty()) settings.erase("--alpha-scan");
    if (method.readableRuleParameter.empty()) settings.erase("--min-coherence");
    return settings;
}

/// True when --only's @a pairs (none: every pair) select @a method of the mesh @a stem.
bool selected(const std::vector<std::pair<std::string, std::string>>& pairs, const std::string& stem,
              const std::string& method)
{
    return pairs.empty() || std::find(pairs.begin(), pairs.end(), std::pair{stem, method}) != pairs.end();
}

/// True when @a results holds, for @a stem, the measures of every method and its seconds at every
/// resolution.
bool finished(const nlohmann::json& results, const std::string& stem, const std::vector<std::string>& methods,
              const std::vector<int>& resolutions)
{
    if (!results.contains(stem)) return false;
    for (const std::string& m : methods) {
        const nlohmann::json& entry = results.at(stem).contains(m) ? results.at(stem).at(m) : nlohmann::json();
        for (const char* key : {"visibility", "voxel_visibility", "paper_literal", "front_visibility", "coherence", "seconds"})
            if (!entry.is_object() || !entry.contains(key)) return false;
        for (int r : resolutions)
            if (!entry.at("seconds").contains(std::to_string(r))) return false;
    }
    return true;
}

/// Refuses a mesh that is no file but a method's name or a number: the rest of a list given to
/// --methods or --opt-res with spaces instead of commas, which the command line took for meshes.
void rejectListsGivenWithSpaces(const std::vector<std::string>& meshes)
{
    const std::vector<std::string> methods = render::methodNames();
    for (const std::string& mesh : meshes) {
        if (mesh.rfind(core::kScenePrefix, 0) == 0 || std::filesystem::exists(mesh)) continue;
        if (std::find(methods.begin(), methods.end(), mesh) != methods.end())
            throw InputError(mesh + ": file not found, and a method's name: --methods takes them comma-separated "
                             "(--methods neugebauer,mirror)");
        if (!mesh.empty() && mesh.find_first_not_of("0123456789") == std::string::npos)
            throw InputError(mesh + ": file not found, and a number: --opt-res takes them comma-separated "
                             "(--opt-res 100,1000)");
    }
}

}  // namespace

Command addEvaluateCommand(CLI::App& app)
{
    struct Options {
        std::vector<std::string> meshes;
        MeshOptions mesh;
        std::vector<std::string> methods = render::methodNames();
        std::vector<int> optResolutions{100};
        int displayResolution = 1000;
        int pictureResolution = 0;
        int views = 1;
        std::optional<double> fovYDeg;  ///< none: each view framed for its method
        OptimizationOptions optimization;
        std::string json, markdown, pictures, cacheDir;
        std::vector<std::string> only;
        bool resume = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("evaluate", "Visibility and timing tables of the methods (paper Tab. 1, 2)");
    options->mesh.addTo(*command, &options->meshes);
    // Each list option takes one comma-separated argument, so the meshes may follow it.
    command->add_option("--methods", options->methods, "Methods to compare, comma-separated (default: every method)")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->capture_default_str();
    command->add_option("--opt-res", options->optResolutions, "Optimisation resolutions, comma-separated")
        ->check(optimizationResolutionRange())
        ->delimiter(',')
        ->allow_extra_args(false)
        ->capture_default_str();
    command->add_option("--display-res", options->displayResolution, "Resolution of pictures and of the reported visibility")
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    command
        ->add_option("--views", options->views,
                     "Also the surface the best view and the visited views adding the most to it show together "
                     "(as optimize --views; visibility energy)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    command->add_option("--fov", options->fovYDeg,
                        "Vertical field of view (degrees); default: each view fitted to its method's picture");
    options->optimization.addTo(*command);
    command->add_option("--json", options->json, "Results as JSON (written after each mesh)");
    command->add_option("--markdown", options->markdown, "Results as Markdown tables (written after each mesh)");
    command->add_flag("--resume", options->resume,
                      "Keep the meshes the --json file already holds for every method and evaluate the others");
    auto* pictures = command->add_option(
        "--pictures", options->pictures,
        "Folder for each method's picture at its best view (made when missing, in an existing folder)");
    command->add_option("--picture-res", options->pictureResolution, "Size of those pictures (default: --display-res)")
        ->needs(pictures)
        ->check(CLI::Range(16, 8192));
    command->add_option("--cache-dir", options->cacheDir, kCacheDirHelp)->check(nonEmpty());
    command->add_option("--only", options->only,
                        "Evaluate only MESH:METHOD (the mesh's file stem; repeatable): one job of an evaluation spread "
                        "over a cluster; `inversevis merge` joins the parts' --json files into the tables")
        ->allow_extra_args(false);

    return {command, [options] {
        for (auto m = options->methods.begin(); m != options->methods.end(); ++m) {
            render::methodInfo(*m);  // validate names first
            if (std::find(m + 1, options->methods.end(), *m) != options->methods.end())
                throw InputError("--methods: " + *m + " is given twice");  // it made two equal columns
        }
        rejectListsGivenWithSpaces(options->meshes);
        if (options->optResolutions.empty()) throw InputError("--opt-res: give at least one resolution");
        for (auto r = options->optResolutions.begin(); r != options->optResolutions.end(); ++r)
            if (std::find(r + 1, options->optResolutions.end(), *r) != options->optResolutions.end())
                throw InputError("--opt-res: " + std::to_string(*r) + " is given twice");
        std::vector<render::MethodPtr> methods;
        for (const std::string& m : options->methods) methods.push_back(render::makeMethod(m));
        options->mesh.fitReachTo(methods);
        const auto pairs = onlyPairs(options->only, options->meshes, options->methods);
        std::vector<render::MethodPtr> used;  // the methods --only selects (all without it)
        for (const render::MethodPtr& m : methods)
            if (pairs.empty() || std::any_of(pairs.begin(), pairs.end(), [&](const auto& p) { return p.second == m->name(); }))
                used.push_back(m);
        options->optimization.checkUsedBy(used, options->optResolutions);
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        if (options->resume && options->json.empty()) throw InputError("--resume needs --json (the results to resume)");
        // --json may name the results --resume reads: that file is meant to be rewritten.
        checkOutputFiles({jsonOutput(options->json, "--json"), markdownOutput(options->markdown, "--markdown")},
                         readFiles(options->meshes, options->mesh.load.read.scalarFile, "", ""));
        if (!options->pictures.empty()) {
            checkOutputFolder(options->pictures);
            if (std::filesystem::exists(options->pictures) && !std::filesystem::is_directory(options->pictures))
                throw InputError(options->pictures + ": --pictures names a file, not a folder");
            const auto canonical = [](const std::string& path) { return std::filesystem::weakly_canonical(path); };
            for (const auto& [path, option] :
                 {std::pair{options->json, "--json"}, std::pair{options->markdown, "--markdown"}})
                if (!path.empty() && canonical(path) == canonical(options->pictures))
                    throw InputError(options->pictures + ": --pictures and " + option +
                                     " name the same path (one is a folder of pictures, the other a file)");
        }
        nlohmann::json results = nlohmann::json::object();
        if (options->resume && std::filesystem::exists(options->json)) results = readEvaluationJson(options->json);
        // What the figures depend on, kept in every entry: merge and --resume join only entries of one evaluation.
        if (options->views > 1 && optimize::parseEnergyKind(options->optimization.energy) != optimize::EnergyKind::Visibility)
            throw ValueError("--views chooses views by the surface they show together: it needs --energy visibility");
        nlohmann::json settings = options->mesh.settingsJson();
        settings.update(options->optimization.settingsJson());
        settings.update({{"--opt-res", options->optResolutions},
                         {"--display-res", options->displayResolution},
                         {"--fov", options->fovYDeg ? nlohmann::json(*options->fovYDeg) : nlohmann::json()}});
        if (options->views > 1) settings["--views"] = options->views;
        ReportLayout layout{{}, options->methods, options->optResolutions, options->displayResolution};
        for (const std::string& mesh : options->meshes) {
            const std::string stem = core::sourceStem(mesh);
            const auto same = std::find(layout.stems.begin(), layout.stems.end(), stem);
            if (same != layout.stems.end())
                throw InputError(mesh + ": its name '" + stem + "' is also " + options->meshes[same - layout.stems.begin()] +
                                 "'s (the tables, --json and --only name a mesh by its file stem; rename one)");
            layout.stems.push_back(stem);
        }
        // Every mesh is read once before any is evaluated, so a bad one fails in seconds, not after hours;
        // its hash joins its settings (two meshes of one name are not one row).
        std::map<std::string, nlohmann::json> settingsOf;
        for (const std::string& mesh : options->meshes)
            if (std::any_of(options->methods.begin(), options->methods.end(),
                            [&](const std::string& m) { return selected(pairs, core::sourceStem(mesh), m); })) {
                nlohmann::json& of = settingsOf[core::sourceStem(mesh)] = settings;
                of["mesh hash"] = core::toHex(core::meshHash(core::loadSurface(mesh, options->mesh.load).mesh));
            }
        for (const auto& [stem, methods] : results.items()) {
            const bool evaluated = settingsOf.count(stem) > 0;  // else kept as it is: only the run's settings
            for (const auto& [method, entry] : methods.items())
                if (const std::string difference = settingsDifference(
                        entry.is_object() ? entry.value("settings", nlohmann::json()) : nlohmann::json(),
                        settingsUsedBy(evaluated ? settingsOf.at(stem) : settings, render::methodInfo(method)),
                        evaluated);
                    !difference.empty())
                    throw InputError(options->json + ": " + stem + ":" + method + " was evaluated with " + difference +
                                     " in this run; --resume continues an evaluation with its options");
        }
        // The tables show all the --json file holds: the meshes and methods it kept from other runs first.
        std::vector<std::string> keptStems;
        for (const auto& [stem, methods] : results.items()) {
            if (std::find(layout.stems.begin(), layout.stems.end(), stem) == layout.stems.end()) keptStems.push_back(stem);
            for (const auto& [method, entry] : methods.items())
                if (std::find(layout.methods.begin(), layout.methods.end(), method) == layout.methods.end())
                    layout.methods.push_back(method);
        }
        layout.stems.insert(layout.stems.begin(), keptStems.begin(), keptStems.end());
        if (!options->pictures.empty()) std::filesystem::create_directories(options->pictures);
        core::ProgressBar progress(core::logLevel() <= core::LogLevel::Info);
        const std::string cacheFolder = vdb::optionalCacheFolder(options->cacheDir);

        for (const std::string& mesh : options->meshes) {
            std::vector<std::string> methods;  // of this mesh, as --only selects them
            for (const std::string& m : options->methods)
                if (selected(pairs, core::sourceStem(mesh), m)) methods.push_back(m);
            if (methods.empty()) continue;
            if (finished(results, core::sourceStem(mesh), methods, options->optResolutions)) {
                core::logInfo(core::sourceStem(mesh) + ": kept from " + options->json + " (--resume)");
                continue;
            }
            const std::string meshLabel = core::sourceStem(mesh) + " " + std::to_string(&mesh - options->meshes.data() + 1) +
                                          "/" + std::to_string(options->meshes.size());
            progress.setContext(meshLabel);
            const core::SurfaceField field = core::loadSurface(mesh, options->mesh.load);
            const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(
                field.mesh, volumeOptions, vdb::defaultVolumePath(cacheFolder, mesh, field.mesh, volumeOptions),
                &progress);
            const render::RenderScene scene(field, volume);
            const core::ScalarRange range = core::scalarRangeFromData(field.values);
            const std::string stem = core::sourceStem(mesh);
            optimize::EnergyOptions displayOptions = options->optimization.measureOptions(options->displayResolution, range);
            displayOptions.kind = optimize::EnergyKind::Visibility;
            displayOptions.paperLiteral = true;
            displayOptions.reveal = field.hasScalar();
            const optimize::EnergyEvaluator display(scene, displayOptions);
            nlohmann::json meshResults = nlohmann::json::object();
            for (const std::string& methodName : methods) {
                progress.setContext(meshLabel + ", " + methodName);
                const render::MethodPtr start = render::makeMethod(methodName);
                nlohmann::json entry = {{"seconds", nlohmann::json::object()},
                                        {"settings", settingsUsedBy(settingsOf.at(stem), start->info())}};
                optimize::VisitedView best;
                render::RenderOptions picture;  // the display picture of a view (hot spots, several views)
                picture.width = picture.height = options->displayResolution;
                std::optional<render::RenderResult> bestPicture;
                for (std::size_t k = 0; k < options->optResolutions.size(); ++k) {
                    const int resolution = options->optResolutions[k];
                    const optimize::EnergyEvaluator evaluator(scene, options->optimization.energyOptions(resolution, range));
                    const auto ascentEvaluator = options->optimization.ascentEvaluator(scene, resolution, range);
                    const auto finalistEvaluator = options->optimization.finalistEvaluator(scene, resolution, range);
                    const optimize::AnnealingOptions annealing =
                        options->optimization.annealingOptions(std::nullopt, options->fovYDeg);
                    const optimize::AnnealingResult run =
                        optimize::annealViewpoint(evaluator, start, annealing, options->optimization.ascentOptions(),
                                                  ascentEvaluator.get(), &progress, finalistEvaluator.get());
                    entry["seconds"][std::to_string(resolution)] = run.seconds;
                    entry["ascent_res"][std::to_string(resolution)] =
                        ascentEvaluator ? options->optimization.ascentResolution : resolution;
                    const optimize::VisitedView& optimum = run.bestView();
                    const optimize::EnergyValue measured = display.evaluate(optimum.camera, optimum.method);
                    entry["by_resolution"][std::to_string(resolution)] = {{"theta", optimum.thetaDeg},
                                                                          {"phi", optimum.phiDeg},
                                                                          {"fov_y_deg", optimum.camera.fovYDeg},
                                                                          {"params", render::methodToJson(*optimum.method)},
                                                                          {"visibility", measured.energy}};
                    if (run.readable)
                        entry["by_resolution"][std::to_string(resolution)]["readable_rule"] = readableSettingJson(*run.readable);
                    if (k == 0) {
                        best = optimum;
                        if (options->views > 1) {  // chosen among this run's views, on its evaluator's voxels
                            picture.method = best.method;
                            bestPicture = render::renderImage(scene, best.camera, picture);
                            entry["several_views"] =
                                renderSeveralViews(scene, run, evaluator, display, annealing, !options->fovYDeg, picture,
                                                   best.camera, *bestPicture, options->views)
                                    .json;
                        }
                    } else {
                        entry["optimum_shift_deg"][std::to_string(resolution)] =
                            optimize::degreesBetweenViews(best.thetaDeg, best.phiDeg, optimum.thetaDeg, optimum.phiDeg);
                    }
                }
                // Square pictures: the view as the annealing framed and measured it.
                const core::Camera& camera = best.camera;
                const optimize::EnergyValue value = display.evaluate(camera, best.method);
                const optimize::Coherence coherent =
                    optimize::measureCoherence(scene, camera, best.method, options->displayResolution);
                entry.update(measuresJson(value, coherent.value(), displayOptions.reveal));
                if (displayOptions.reveal && !entry.at("reveal").is_null()) {  // the hot spots in the picture
                    picture.method = best.method;
                    if (!bestPicture) bestPicture = render::renderImage(scene, camera, picture);
                    addHotSpotShapes(entry, display, bestPicture->layers);
                }
                entry["theta"] = best.thetaDeg;
                entry["phi"] = best.phiDeg;
                entry["fov_y_deg"] = camera.fovYDeg;
                entry["params"] = render::methodToJson(*best.method);
                entry["display_res"] = options->displayResolution;
                if (!start->info().scannedParameter.empty()) entry["alpha_scan"] = options->optimization.alphaScan;
                if (!options->pictures.empty()) {
                    render::RenderOptions picture;
                    picture.width = picture.height =
                        options->pictureResolution > 0 ? options->pictureResolution : options->displayResolution;
                    picture.method = best.method;
                    picture.shading.scale.range = range;
                    picture.scalarName = field.name;
                    const std::string path = options->pictures + "/" + stem + "-" + methodName + ".png";
                    core::writePng(render::renderImage(scene, camera, picture).figure, path, false);
                    entry["picture"] = path;
                }
                meshResults[methodName] = entry;
                char line[160];
                std::snprintf(line, sizeof line, ": visibility %.1f%% (front %.1f%%), coherence %.3f", 100.0 * value.energy,
                              100.0 * value.front, coherent.value());
                core::logInfo(stem + " " + methodName + line);
            }
            // Only whole meshes (an interrupted one is evaluated again); other methods' results kept.
            if (!results.contains(stem)) results[stem] = nlohmann::json::object();
            results[stem].update(meshResults);
            if (!options->json.empty()) writeJsonFile(results, options->json);
            if (!options->markdown.empty()) writeTextFile(evaluationMarkdown(results, layout), options->markdown);
        }
        const std::string markdown = evaluationMarkdown(results, layout);
        if (!options->markdown.empty()) writeTextFile(markdown, options->markdown);
        std::cout << markdown;
    }};
}

}  // namespace ivis::app
