#include "json_output.h"

#include <ivis/core/json_text.h>
#include <ivis/core/atomic_file.h>
#include <ivis/optimize/hot_spot_rule.h>
#include <ivis/optimize/sampling_bound.h>
#include <ivis/optimize/unseen_map.h>
#include <ivis/render/method_json.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace ivis::app {

nlohmann::json visitedViewJson(const optimize::VisitedView& view)
{
    nlohmann::json json = {{"theta", view.thetaDeg},
                           {"phi", view.phiDeg},
                           {"fov_y_deg", view.camera.fovYDeg},
                           {"energy", view.value.energy},
                           {"front_energy", view.value.front},
                           {"accepted", view.accepted},
                           {"polish", view.polish},
                           {"params", render::methodToJson(*view.method)}};
    if (view.finalValue) json["finalist_energy"] = view.finalValue->energy;
    return json;
}

std::string readableSettingLine(const optimize::ReadableSetting& setting)
{
    const std::string& parameter = setting.method->info().readableRuleParameter;
    char text[200];
    std::snprintf(text, sizeof text,
                  "readable rule: %s %.4g, estimated coherence %.4f on %zu sampled pairs of a %dx%d picture",
                  parameter.c_str(), setting.method->values().at(parameter).at(0), setting.coherence.value(),
                  setting.coherence.pairs, setting.size.x, setting.size.y);
    return text + std::string(setting.keepsMinimum ? "" : " (below --min-coherence even at the tightest rule)");
}

std::string hotSpotChoiceLine(const optimize::HotSpotChoice& choice)
{
    char text[300];
    if (!choice.chosen)
        std::snprintf(text, sizeof text, "hot-spot rule: no view could be judged (every one has a hot spot facing away); "
                      "the best view stays");
    else if (!choice.reads)
        std::snprintf(text, sizeof text, "hot-spot rule: none of the %d views judged shows every hot spot %.0f%% seen and "
                      "as one place; the nearest to it is taken (shortfall %.3f, %.0f%% of the best view's energy)",
                      choice.judged, 100.0 * optimize::kMinHotSpotSeen, choice.shortfall, 100.0 * choice.energyRatio);
    else
        std::snprintf(text, sizeof text, "hot-spot rule: judged view %d is the best whose every hot spot reads as one "
                      "place (%.0f%% of the best view's energy)", choice.judged, 100.0 * choice.energyRatio);
    return text;
}

nlohmann::json measuresJson(const optimize::EnergyValue& value, double coherence, bool withReveal)
{
    nlohmann::json json = {{"visibility", value.energy},
                           {"voxel_visibility", value.voxelVisibility},
                           {"paper_literal", value.paperLiteral},
                           {"front_visibility", value.front},
                           {"coherence", coherence}};
    if (withReveal)
        json["reveal"] = value.reveal.perRegion.empty()  // no important surface: nothing to reveal
                             ? nlohmann::json()
                             : nlohmann::json{{"total", value.reveal.total},
                                              {"direct", value.reveal.direct},
                                              {"per_region", value.reveal.perRegion}};
    return json;
}

void addHotSpotShapes(nlohmann::json& measures, const optimize::EnergyEvaluator& evaluator,
                      const core::ImageLayers& layers)
{
    if (!evaluator.revealMeasure() || !measures.contains("reveal") || measures.at("reveal").is_null()) return;
    measures["reveal"]["shapes"] = optimize::hotSpotShapesJson(optimize::hotSpotShapes(*evaluator.revealMeasure(), layers));
}

nlohmann::json pictureMeasuresJson(const render::RenderScene& scene, const core::Camera& camera,
                                   const render::MethodPtr& method, int resolution,
                                   const core::ScalarRange& importanceRange, double coherence,
                                   const core::ImageLayers& layers, core::Image* unseen)
{
    optimize::EnergyOptions options;
    options.kind = optimize::EnergyKind::Visibility;
    options.resolution = resolution;
    options.paperLiteral = true;
    options.reveal = scene.field().hasScalar();
    options.importanceRange = importanceRange;
    const optimize::EnergyEvaluator evaluator(scene, options);
    const optimize::EnergyValue value = evaluator.evaluate(camera, method);
    nlohmann::json measures = measuresJson(value, coherence, options.reveal);
    addHotSpotShapes(measures, evaluator, layers);
    const std::size_t surfacePixels = value.pixelsDirect + value.pixelsIndirect;
    measures["surface_pixels"] = surfacePixels;
    measures["even_bound"] =
        surfacePixels > 0 ? optimize::evenSamplingBound(scene.mesh(), *evaluator.surfaceVoxels(), surfacePixels) : 0.0;
    if (unseen) *unseen = optimize::unseenMap(scene, camera, *evaluator.surfaceVoxels(), value.seenVoxels, resolution);
    return measures;
}

std::string measuresLine(const nlohmann::json& measures)
{
    auto figure = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3f", value);
        return std::string(text);
    };
    std::string line = "surface visibility " + figure(measures.at("visibility")) + " (front " +
                       figure(measures.at("front_visibility")) + "), by voxel count " +
                       figure(measures.at("voxel_visibility")) + ", paper-literal " +
                       figure(measures.at("paper_literal")) + ", coherence " + figure(measures.at("coherence"));
    if (measures.contains("even_bound"))
        line += " (the same number of surface pixels spread evenly: " + figure(measures.at("even_bound")) + ")";
    if (measures.contains("reveal")) {
        const nlohmann::json& reveal = measures.at("reveal");
        line += reveal.is_null() ? ", reveal: no important surface" : ", reveal " + figure(reveal.at("total"));
        if (!reveal.is_null() && reveal.contains("shapes")) {
            line += ", hot spots (share in one place / outline ratio)";
            for (const nlohmann::json& shape : reveal.at("shapes"))
                line += " " + figure(shape.at("largest_share")) + "/" + figure(shape.at("outline_ratio"));
        }
    }
    return line;
}

void writeTextFile(const std::string& text, const std::string& path)
{
    core::writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << text;
        if (!out) throw std::runtime_error("write failed");
    });
}

void writeJsonFile(const nlohmann::json& json, const std::string& path)
{
    writeTextFile(core::jsonText(json, 2) + "\n", path);
}

}  // namespace ivis::app
