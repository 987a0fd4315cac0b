#include "view_file.h"

#include "json_output.h"

#include <ivis/core/camera_json.h>
#include <ivis/core/errors.h>
#include <ivis/render/method_json.h>

#include <filesystem>
#include <fstream>

namespace ivis::app {
namespace {

const char* sideName(core::LegendSide side)
{
    switch (side) {
    case core::LegendSide::Left: return "left";
    case core::LegendSide::Bottom: return "bottom";
    case core::LegendSide::Right: break;
    }
    return "right";
}

ViewFile viewFromJson(const nlohmann::json& json)
{
    if (!json.is_object()) throw std::invalid_argument("expected a JSON object");
    const int version = json.at("inversevis_view").get<int>();
    if (version < 1 || version > kViewFileVersion)
        throw std::invalid_argument("version " + std::to_string(version) + " (this program reads 1 to " +
                                    std::to_string(kViewFileVersion) + ")");
    ViewFile view;
    view.camera = core::cameraFromJson(json.at("camera"));
    const nlohmann::json& size = json.at("size");
    if (!size.is_array() || size.size() != 2) throw std::invalid_argument("'size' must be [width, height]");
    view.width = size[0].get<int>();
    view.height = size[1].get<int>();
    if (view.width < 1 || view.height < 1 || view.width > 32768 || view.height > 32768)
        throw std::invalid_argument("'size' must be 1 to 32768 pixels each way");
    view.method = render::methodFromJson(json.at("method"));
    view.scalar = json.value("scalar", std::string());
    view.scalarFile = json.value("scalar_file", std::string());
    view.hotSpots = json.value("hotspots", 0);
    if (view.hotSpots < 0 || view.hotSpots > 6) throw std::invalid_argument("'hotspots' must be 0 to 6");
    view.colormap = json.at("colormap").get<std::string>();
    core::colormap(view.colormap);  // known
    const nlohmann::json& scale = json.at("scale");
    const nlohmann::json& range = scale.at("range");
    if (!range.is_array() || range.size() != 2) throw std::invalid_argument("'scale.range' must be [lo, hi]");
    view.scale.range = {range[0].get<float>(), range[1].get<float>()};
    view.scale.log = scale.at("log").get<bool>();
    view.scale.invert = scale.at("invert").get<bool>();
    if (!(view.scale.range.lo <= view.scale.range.hi) || (view.scale.log && !(view.scale.range.lo > 0.0f)))
        throw std::invalid_argument("'scale.range' must be ordered (and positive on a log scale)");
    view.units = json.value("units", std::string());
    view.legend = !json.at("legend").is_null();
    if (view.legend) view.legendSide = core::legendSideFromName(json.at("legend").get<std::string>());
    view.outline = json.at("outline").get<bool>();
    view.shadows = json.at("shadows").get<bool>();
    view.shadeIndirect = json.at("shade_indirect").get<bool>();
    return view;
}

}  // namespace

ViewFile viewOfPicture(const core::Camera& camera, const render::RenderOptions& options, const core::SurfaceLoadOptions& load,
                       const core::Similarity& meshUnits)
{
    ViewFile view;
    view.meshUnits = meshUnits;
    view.camera = camera;
    view.width = options.width;
    view.height = options.height;
    view.method = options.method;
    view.scalar = load.read.scalarName;
    if (!load.read.scalarFile.empty()) view.scalarFile = std::filesystem::absolute(load.read.scalarFile).string();
    view.hotSpots = load.hotSpots;
    view.colormap = options.shading.colormap;
    view.scale = options.shading.scale;
    view.units = options.units;
    view.legend = options.legend;
    view.legendSide = options.legendSide;
    view.outline = options.outline;
    view.shadows = options.shading.shadows;
    view.shadeIndirect = options.shading.shadeIndirect;
    return view;
}

nlohmann::json viewToJson(const ViewFile& view)
{
    return {{"inversevis_view", kViewFileVersion},
            {"camera", core::cameraToJson(view.camera)},
            {"size", {view.width, view.height}},
            {"method", render::methodToJson(*view.method)},
            {"scalar", view.scalar},
            {"scalar_file", view.scalarFile},
            {"hotspots", view.hotSpots},
            {"colormap", view.colormap},
            {"scale", {{"range", {view.scale.range.lo, view.scale.range.hi}}, {"log", view.scale.log}, {"invert", view.scale.invert}}},
            {"units", view.units},
            {"legend", view.legend ? nlohmann::json(sideName(view.legendSide)) : nlohmann::json()},
            {"outline", view.outline},
            {"shadows", view.shadows},
            {"shade_indirect", view.shadeIndirect},
            {"mesh_units", core::meshUnitsJson(view.meshUnits)}};
}

ViewFile readViewFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open view file");
    try {
        return viewFromJson(nlohmann::json::parse(in));
    } catch (const std::exception& e) {
        throw InputError(path + ": bad view file (" + e.what() + ")");
    }
}

void writeViewFile(const ViewFile& view, const std::string& path) { writeJsonFile(viewToJson(view), path); }

}  // namespace ivis::app
