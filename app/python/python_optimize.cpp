#include "python_optimize.h"

#include "python_call.h"

#include "../json_output.h"
#include "../optimization_options.h"
#include "../several_views.h"

#include <ivis/core/camera.h>
#include <ivis/core/errors.h>
#include <ivis/core/number_text.h>
#include <ivis/optimize/coherence.h>
#include <ivis/optimize/picture.h>
#include <ivis/optimize/picture_measure.h>
#include <ivis/optimize/viewpoint_annealing.h>
#include <ivis/render/method_json.h>
#include <ivis/render/picture_extent.h>

#include <cmath>

namespace py = pybind11;

namespace ivis::python {
namespace {

/// `optimize`'s settings from @a request, each checked as the command line checks its flag.
app::OptimizationOptions optimizationOptions(const OptimizeRequest& request, const render::MethodPtr& method)
{
    app::OptimizationOptions o;
    if (request.energy != "visibility" && request.energy != "scalar")
        throw ValueError("energy '" + request.energy + "': visibility or scalar");
    o.energy = request.energy;
    if (request.gamma) {
        if (request.energy != "scalar")
            throw ValueError("gamma weights the directly visible part of the scalar energy; energy is " + request.energy);
        if (!(*request.gamma >= 0.0f && *request.gamma <= 1000.0f))
            throw ValueError("gamma " + core::shortNumber(*request.gamma) + " must lie in [0, 1000]");
        o.gamma = *request.gamma;
    }
    if (request.optResolution < optimize::kMinOptimizationResolution ||
        request.optResolution > optimize::kMaxOptimizationResolution)
        throw ValueError("opt_res " + std::to_string(request.optResolution) + " is out of range (" +
                         std::to_string(optimize::kMinOptimizationResolution) + " to " +
                         std::to_string(optimize::kMaxOptimizationResolution) + ")");
    if (request.ascentResolution < 0 ||
        (request.ascentResolution > 0 && request.ascentResolution < optimize::kMinOptimizationResolution) ||
        (request.ascentResolution > 0 && request.ascentResolution >= request.optResolution))
        throw ValueError("ascent_res " + std::to_string(request.ascentResolution) + " must lie from " +
                         std::to_string(optimize::kMinOptimizationResolution) + " to below opt_res (" +
                         std::to_string(request.optResolution) + "; 0: the ascent at opt_res)");
    o.ascentResolution = request.ascentResolution;
    if (request.steps < 0 || request.steps > 1000000)
        throw ValueError("steps " + std::to_string(request.steps) + " is out of range (0 to 1000000)");
    o.steps = request.steps;
    o.seed = request.seed;
    if (request.finalists < 0 || request.finalists > 1000)
        throw ValueError("finalists " + std::to_string(request.finalists) + " is out of range (0 to 1000)");
    o.finalists = request.finalists;
    if (request.hotSpotViews) {
        if (*request.hotSpotViews < 0 || *request.hotSpotViews > 1000)
            throw ValueError("hot_spot_views " + std::to_string(*request.hotSpotViews) + " is out of range (0 to 1000)");
        if (*request.hotSpotViews > 0 && request.energy != "scalar")
            throw ValueError("hot_spot_views: the hot-spot rule chooses among views by the scalar energy; energy is " +
                             request.energy);
        o.hotSpotViews = *request.hotSpotViews;
    }
    if (!(request.look.minCoherence >= 0.0 && request.look.minCoherence <= 1.0))  // NaN too
        throw ValueError("min_coherence " + std::to_string(request.look.minCoherence) + " must lie in [0, 1]");
    // A rule given as a parameter is kept, as `optimize --stable-shift` keeps it.
    const std::string& rule = method->info().readableRuleParameter;
    // As `optimize --min-coherence` with such a method refuses it (the default and 0 ask for nothing).
    if (rule.empty() && request.look.minCoherence != optimize::kDefaultMinCoherence && request.look.minCoherence != 0.0)
        throw ValueError("min_coherence: " + method->name() +
                         " has no rule for drawing rays to loosen (inversevis-wrap: stable_shift)");
    o.minCoherence = rule.empty() || request.look.parameters.contains(rule) ? 0.0 : request.look.minCoherence;
    o.checkUsedBy({method}, {request.optResolution});
    return o;
}

}  // namespace

std::shared_ptr<Picture> optimizeMesh(const std::shared_ptr<Mesh>& drawn, const OptimizeRequest& request,
                                      const py::object& progress)
{
    Mesh& mesh = *drawn;
    PictureLook look = pictureLook(request.look);
    const render::MethodPtr method = look.options.method;
    const app::OptimizationOptions settings = optimizationOptions(request, method);
    if (double(look.options.width) <= render::kFramingMargin * look.options.height)
        throw ValueError("a framed picture of " + std::to_string(look.options.width) + "x" +
                         std::to_string(look.options.height) + " needs a wider picture");
    std::optional<glm::dvec2> startAngles;
    if (request.start) {
        if (!std::isfinite(request.start->first) || !std::isfinite(request.start->second))
            throw ValueError("start (" + core::shortNumber(request.start->first) + ", " +
                             core::shortNumber(request.start->second) + "): theta and phi must be finite degrees");
        // As `optimize --theta --phi` starts: the angles of the camera they place (theta -30 is 30
        // on the other side), so that both search alike.
        startAngles = core::Camera::fromAngles(request.start->first, request.start->second, core::kCameraDistance,
                                               core::kDefaultFovYDeg)
                          .angles();
    }

    // What the scalar shown allows, before anything is built.
    if (settings.energy == "scalar" || !look.colourKeywords.empty()) {
        const core::SurfaceField shown = mesh.shown(request.look.load);
        if (settings.energy == "scalar" && !shown.hasScalar())
            throw InputError(mesh.source() + ": the scalar energy needs a scalar (see scalar=)");
        look.checkColourKeywords(mesh, shown);
    }

    if (request.views < 1 || request.views > 16)
        throw ValueError("views " + std::to_string(request.views) + " is out of range (1 to 16)");
    if (request.views > 1 && settings.energy != "visibility")
        throw ValueError("views: several views are chosen by the surface they show together: they need energy='visibility'");
    auto made = std::make_shared<Picture>();
    runReleased(
        [&](core::Interrupter& interrupter) {
            const std::shared_ptr<const Scene> scene = mesh.scene(request.look.load, look.volume, &interrupter);
            look.colourBy(mesh, scene->field);
            const render::RenderScene& renderScene = *scene->render;
            const core::ScalarRange range = look.options.shading.scale.range;
            // The search, as `inversevis optimize` runs it (its views framed for their method).
            const optimize::EnergyEvaluator evaluator(renderScene, settings.energyOptions(request.optResolution, range));
            const auto ascent = settings.ascentEvaluator(renderScene, request.optResolution, range);
            const auto finalist = settings.finalistEvaluator(renderScene, request.optResolution, range);
            const optimize::AnnealingResult result =
                optimize::annealViewpoint(evaluator, method, settings.annealingOptions(startAngles, std::nullopt),
                                          settings.ascentOptions(), ascent.get(), &interrupter, finalist.get());
            const optimize::VisitedView& best = result.bestView();
            // Its picture at the asked size, framed, and the measures of that view.
            const core::Camera camera = optimize::framedCamera(renderScene, best.camera, *best.method,
                                                               look.options.width, look.options.height);
            look.options.method = best.method;
            made->result = render::renderImage(renderScene, camera, look.options, &interrupter);
            optimize::EnergyOptions measure = settings.measureOptions(look.options.height, range);
            measure.kind = optimize::EnergyKind::Visibility;
            measure.paperLiteral = true;
            measure.reveal = scene->field.hasScalar();
            const optimize::EnergyEvaluator measureEvaluator(renderScene, measure);
            const optimize::EnergyValue measured = optimize::measurePicture(measureEvaluator, made->result.layers);
            const double coherence = optimize::mappingCoherence(made->result.layers).value();
            made->camera = camera;
            made->look = look.options;
            made->load = request.look.load;
            made->mesh = drawn;
            made->volume = look.volume;
            made->meshUnits = scene->field.normalization;
            made->method = render::methodToJson(*best.method);
            made->measures = app::measuresJson(measured, coherence, measure.reveal);
            app::addHotSpotShapes(made->measures, measureEvaluator, made->result.layers);
            made->measures["seconds"] = made->result.stats.seconds;
            made->measures["pixels_direct"] = made->result.stats.pixelsDirect;
            made->measures["pixels_indirect"] = made->result.stats.pixelsIndirect;
            made->measures["volume_cache"] = scene->volumePath;
            nlohmann::json visited = nlohmann::json::array();
            for (const optimize::VisitedView& view : result.visited) visited.push_back(app::visitedViewJson(view));
            made->optimization = {{"energy", settings.energy},
                                  {"opt_res", request.optResolution},
                                  {"seed", request.seed},
                                  {"seconds", result.seconds},
                                  {"evaluations", result.evaluations},
                                  {"theta", best.thetaDeg},
                                  {"phi", best.phiDeg},
                                  {"energy_value", best.value.energy},
                                  {"front_energy_value", best.value.front},
                                  {"visited", visited}};
            if (result.hotSpots) made->optimization["hot_spot_rule"] = optimize::hotSpotChoiceJson(*result.hotSpots);
            if (result.readable) made->optimization["readable_rule"] = optimize::readableSettingJson(*result.readable);
            if (request.views > 1) {  // as `optimize --views`: the further views, their pictures and union
                const app::SeveralViews set =
                    app::renderSeveralViews(renderScene, result, evaluator, measureEvaluator,
                                            settings.annealingOptions(startAngles, std::nullopt), true, look.options,
                                            camera, made->result, request.views);
                for (std::size_t k = 0; k < set.views.size(); ++k) {
                    auto view = std::make_shared<Picture>();
                    view->result = set.views[k].picture;
                    view->camera = set.views[k].camera;
                    view->look = look.options;
                    view->look.method = set.views[k].method;
                    view->load = made->load;
                    view->mesh = drawn;
                    view->volume = look.volume;
                    view->meshUnits = made->meshUnits;
                    view->method = render::methodToJson(*set.views[k].method);
                    view->measures = set.json.at("views").at(k);
                    view->transparent = request.look.transparent;
                    made->views.push_back(view);
                }
                made->viewsFigure = set.figure;
                made->optimization["several_views"] = set.json;
            }
        },
        progress);
    made->transparent = request.look.transparent;
    return made;
}

}  // namespace ivis::python
