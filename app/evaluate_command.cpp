// `inversevis evaluate MESH...`: the paper's Table 1 with METHOD.md's measures at each method's best
// view (surface visibility with its front-only part, paper-literal visibility, mapping coherence and,
// with a scalar, hot-spot reveal) and Table 2 (viewpoint optimisation seconds per resolution).
#include "commands.h"
#include "json_output.h"
#include "mesh_options.h"
#include "method_options.h"
#include "optimization_options.h"

#include <ivis/core/atomic_file.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/log.h>
#include <ivis/core/surface_source.h>
#include <ivis/optimize/coherence.h>
#include <ivis/render/method_json.h>
#include <ivis/render/method_registry.h>
#include <ivis/render/renderer.h>
#include <ivis/vdb/volume_cache.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace ivis::app {
namespace {

/// Great-circle angle in degrees between two camera directions given by their angles.
double angleBetweenViews(double theta1, double phi1, double theta2, double phi2)
{
    auto direction = [](double theta, double phi) {
        const double t = theta * M_PI / 180.0, p = phi * M_PI / 180.0;
        return glm::dvec3(std::sin(t) * std::sin(p), std::cos(t), std::sin(t) * std::cos(p));
    };
    const double c = glm::dot(direction(theta1, phi1), direction(theta2, phi2));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

/// A Markdown table with a row per mesh and a column per method.
class MethodTable {
public:
    explicit MethodTable(const std::vector<std::string>& methods)
    {
        mText << "| Surface |";
        for (const auto& m : methods) mText << " " << m << " |";
        mText << "\n|---|";
        for (std::size_t i = 0; i < methods.size(); ++i) mText << "---|";
        mText << "\n";
    }
    /// @brief Starts the row of mesh @a stem.
    void startRow(const std::string& stem) { mText << "| " << stem << " |"; }
    /// @brief Adds the next method's cell.
    void cell(const std::string& text) { mText << " " << text << " |"; }
    /// @brief Ends the row.
    void endRow() { mText << "\n"; }
    std::string str() const { return mText.str(); }

private:
    std::ostringstream mText;
};

std::string percent(double fraction)
{
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%.1f", 100.0 * fraction);
    return buffer;
}

std::string fixed(double value, int digits)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

/// "total (direct) [region, region, ...]" in percent.
std::string revealText(const optimize::RevealValue& reveal)
{
    std::string text = percent(reveal.total) + " (" + percent(reveal.direct) + ") [";
    for (std::size_t i = 0; i < reveal.perRegion.size(); ++i) text += (i ? ", " : "") + percent(reveal.perRegion[i]);
    return text + "]";
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
        double fovYDeg = core::kDefaultFovYDeg;
        OptimizationOptions optimization;
        std::string json, markdown, pictures, cacheDir = ".";
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("evaluate", "Visibility and timing tables of the methods (paper Tab. 1, 2)");
    options->mesh.addTo(*command, "--volume-res", &options->meshes);
    command->add_option("--methods", options->methods, "Methods to compare (default: every method)")->delimiter(',')->capture_default_str();
    command->add_option("--opt-res", options->optResolutions, "Optimisation resolutions")->delimiter(',')
        ->capture_default_str();
    command->add_option("--display-res", options->displayResolution, "Resolution of pictures and of the reported visibility")
        ->capture_default_str();
    command->add_option("--fov", options->fovYDeg, "Vertical field of view (degrees)")->capture_default_str();
    options->optimization.addTo(*command);
    command->add_option("--json", options->json, "Results as JSON");
    command->add_option("--markdown", options->markdown, "Results as Markdown tables");
    command->add_option("--pictures", options->pictures, "Folder for each method's picture at its best view");
    command->add_option("--picture-res", options->pictureResolution, "Size of those pictures (default: --display-res)")
        ->check(CLI::Range(16, 8192));
    command->add_option("--cache-dir", options->cacheDir, "Folder for volume caches")->capture_default_str();

    return {command, [options] {
        for (const std::string& m : options->methods) render::methodInfo(m);  // validate names first
        if (options->optResolutions.empty()) throw InputError("--opt-res: give at least one resolution");
        const vdb::VolumeOptions volumeOptions = options->mesh.volumeOptions();
        for (const std::string& m : options->methods) checkMethodFitsVolume(*render::makeMethod(m), volumeOptions);
        if (!options->pictures.empty()) std::filesystem::create_directories(options->pictures);
        nlohmann::json results = nlohmann::json::object();
        MethodTable visibility(options->methods), literal(options->methods), coherence(options->methods),
            reveal(options->methods);
        bool anyReveal = false;
        std::ostringstream table2;
        table2 << "| Surface |";
        for (const auto& m : options->methods)
            for (int r : options->optResolutions) table2 << " " << m << " " << r << " |";
        table2 << "\n|---|";
        for (std::size_t i = 0; i < options->methods.size() * options->optResolutions.size(); ++i) table2 << "---|";
        table2 << "\n";

        for (const std::string& mesh : options->meshes) {
            const core::SurfaceField field = core::loadSurface(mesh, options->mesh.load);
            const vdb::SurfaceVolume volume = vdb::loadOrBuildVolume(
                field.mesh, volumeOptions, defaultVolumePath(options->cacheDir, mesh, volumeOptions.resolution));
            const render::RenderScene scene(field, volume);
            const core::ScalarRange range = core::scalarRangeFromData(field.values);
            const std::string stem = core::sourceStem(mesh);
            optimize::EnergyOptions displayOptions = options->optimization.measureOptions(options->displayResolution, range);
            displayOptions.kind = optimize::EnergyKind::Visibility;
            displayOptions.paperLiteral = true;
            displayOptions.reveal = field.hasScalar();
            anyReveal |= displayOptions.reveal;
            const optimize::EnergyEvaluator display(scene, displayOptions);
            for (MethodTable* table : {&visibility, &literal, &coherence, &reveal}) table->startRow(stem);
            table2 << "| " << stem << " |";
            for (const std::string& methodName : options->methods) {
                const render::MethodPtr start = render::makeMethod(methodName);
                nlohmann::json entry = {{"seconds", nlohmann::json::object()}};
                optimize::VisitedView best;
                for (std::size_t k = 0; k < options->optResolutions.size(); ++k) {
                    const int resolution = options->optResolutions[k];
                    const optimize::EnergyEvaluator evaluator(scene, options->optimization.energyOptions(resolution, range));
                    const auto ascentEvaluator = options->optimization.ascentEvaluator(scene, resolution, range);
                    const optimize::AnnealingResult run = optimize::annealViewpoint(
                        evaluator, start, options->optimization.annealingOptions(90.0, 0.0, options->fovYDeg),
                        options->optimization.ascentOptions(), ascentEvaluator.get());
                    entry["seconds"][std::to_string(resolution)] = run.seconds;
                    entry["ascent_res"][std::to_string(resolution)] =
                        ascentEvaluator ? options->optimization.ascentResolution : resolution;
                    table2 << " " << std::lround(run.seconds * 10.0) / 10.0 << " |";
                    const optimize::VisitedView& optimum = run.bestView();
                    const optimize::EnergyValue measured =
                        display.evaluate(core::Camera::fromAngles(optimum.thetaDeg, optimum.phiDeg, core::kCameraDistance, options->fovYDeg),
                                     optimum.method);
                    entry["by_resolution"][std::to_string(resolution)] = {{"theta", optimum.thetaDeg},
                                                                          {"phi", optimum.phiDeg},
                                                                          {"params", render::methodToJson(*optimum.method)},
                                                                          {"visibility", measured.energy}};
                    if (k == 0) {
                        best = optimum;
                    } else {
                        entry["optimum_shift_deg"][std::to_string(resolution)] =
                            angleBetweenViews(best.thetaDeg, best.phiDeg, optimum.thetaDeg, optimum.phiDeg);
                    }
                }
                const core::Camera camera = core::Camera::fromAngles(best.thetaDeg, best.phiDeg, core::kCameraDistance, options->fovYDeg);
                const optimize::EnergyValue value = display.evaluate(camera, best.method);
                const optimize::Coherence coherent =
                    optimize::measureCoherence(scene, camera, best.method, options->displayResolution);
                entry.update(measuresJson(value, coherent, displayOptions.reveal));
                entry["theta"] = best.thetaDeg;
                entry["phi"] = best.phiDeg;
                entry["params"] = render::methodToJson(*best.method);
                if (!start->info().scannedParameter.empty()) entry["alpha_scan"] = options->optimization.alphaScan;
                visibility.cell(percent(value.energy) + " (" + percent(value.front) + ")");
                literal.cell(percent(value.paperLiteral));
                coherence.cell(fixed(coherent.value(), 3));
                reveal.cell(displayOptions.reveal ? revealText(value.reveal) : "-");
                if (!options->pictures.empty()) {
                    render::RenderOptions picture;
                    picture.width = picture.height =
                        options->pictureResolution > 0 ? options->pictureResolution : options->displayResolution;
                    picture.method = best.method;
                    picture.shading.range = range;
                    picture.scalarName = field.name;
                    const std::string path = options->pictures + "/" + stem + "-" + methodName + ".png";
                    core::writePng(render::renderImage(scene, camera, picture).image, path, false);
                    entry["picture"] = path;
                }
                results[stem][methodName] = entry;
                core::logInfo(stem + " " + methodName + ": visibility " + percent(value.energy) + "% (front " +
                              percent(value.front) + "%), coherence " + fixed(coherent.value(), 3));
            }
            for (MethodTable* table : {&visibility, &literal, &coherence, &reveal}) table->endRow();
            table2 << "\n";
        }
        if (!options->json.empty()) writeJsonFile(results, options->json);
        std::string markdown =
            "## Surface visibility in percent at each method's best view (front-only in brackets)\n\n" +
            visibility.str() + "\n## Paper-literal visibility in percent (visited / marked voxels), same views\n\n" +
            literal.str() + "\n## Mapping coherence at " + std::to_string(options->displayResolution) + "^2 pixels, same views\n\n" +
            coherence.str();
        if (anyReveal)
            markdown += "\n## Hot-spot reveal in percent of the important surface: total (direct) [each region]\n\n" +
                        reveal.str();
        markdown += "\n## Viewpoint optimisation, seconds per optimisation resolution\n\n" + table2.str();
        if (!options->markdown.empty())
            core::writeAtomically(options->markdown, [&](const std::string& path) {
                std::ofstream out(path);
                out << markdown;
                if (!out) throw std::runtime_error("write failed");
            });
        std::cout << markdown;
    }};
}

}  // namespace ivis::app
