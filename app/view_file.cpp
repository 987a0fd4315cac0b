#include "view_file.h"

#include "json_output.h"

#include <ivis/core/camera_json.h>
#include <ivis/core/errors.h>
#include <ivis/core/file_bytes.h>
#include <ivis/core/json_text.h>
#include <ivis/core/hot_spots.h>
#include <ivis/core/json_numbers.h>
#include <ivis/render/method_json.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

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

/// The whole number @a json, within [lo, hi] (a float, or a number beyond an int, is refused: its
/// conversion would be undefined or silently truncated).
int wholeNumber(const nlohmann::json& json, const char* what, int lo, int hi)
{
    if (!json.is_number_integer() || json.get<std::int64_t>() < lo || json.get<std::int64_t>() > hi)
        throw std::invalid_argument(std::string("'") + what + "' must be a whole number from " + std::to_string(lo) +
                                    " to " + std::to_string(hi));
    return int(json.get<std::int64_t>());
}

/// The number @a json as a finite float.
float finiteFloat(const nlohmann::json& json, const char* what)
{
    if (!core::isFiniteFloat(json))
        throw std::invalid_argument(std::string("'") + what + "' must be a finite number");
    return json.get<float>();
}

/// @a json's member @a key, which must be an object (the JSON library's "key 'KEY' not found"
/// when it is missing).
const nlohmann::json& objectAt(const nlohmann::json& json, const char* key)
{
    const nlohmann::json& member = json.at(key);
    if (!member.is_object()) throw std::invalid_argument(std::string("'") + key + "' must be an object");
    return member;
}

/// @a json's member @a key as a bool, or @a fallback when it is missing and one is given.
bool flagAt(const nlohmann::json& json, const char* key, std::optional<bool> fallback = std::nullopt)
{
    if (fallback && !json.contains(key)) return *fallback;
    const nlohmann::json& member = json.at(key);
    if (!member.is_boolean()) throw std::invalid_argument(std::string("'") + key + "' must be true or false");
    return member.get<bool>();
}

/// @a json's member @a key as a string, or @a fallback when it is missing and one is given.
std::string textAt(const nlohmann::json& json, const char* key, std::optional<std::string> fallback = std::nullopt)
{
    if (fallback && !json.contains(key)) return *fallback;
    const nlohmann::json& member = json.at(key);
    if (!member.is_string()) throw std::invalid_argument(std::string("'") + key + "' must be a string");
    return member.get<std::string>();
}

ViewFile viewFromJson(const nlohmann::json& json)
{
    if (!json.is_object()) throw std::invalid_argument("expected a JSON object");
    const nlohmann::json& versionJson = json.at("inversevis_view");
    // A float version (8.9e93 in the fuzz run) made the cast to int undefined.
    if (!versionJson.is_number_integer()) throw std::invalid_argument("'inversevis_view' must be a whole number");
    // Compared as a double: an integer beyond int64 (read as unsigned) would wrap round to -1.
    if (versionJson.get<double>() < 1.0 || versionJson.get<double>() > double(kViewFileVersion))
        throw std::invalid_argument("version " + versionJson.dump() + " (this program reads 1 to " +
                                    std::to_string(kViewFileVersion) + ")");
    ViewFile view;
    view.camera = core::cameraFromJson(json.at("camera"));
    const nlohmann::json& size = json.at("size");
    if (!size.is_array() || size.size() != 2) throw std::invalid_argument("'size' must be [width, height]");
    view.width = wholeNumber(size[0], "size", 1, 32768);
    view.height = wholeNumber(size[1], "size", 1, 32768);
    view.method = render::methodFromJson(json.at("method"));
    view.scalar = textAt(json, "scalar", "");
    view.scalarFile = textAt(json, "scalar_file", "");
    view.cellToPoint = flagAt(json, "cell_to_point", false);
    view.hotSpots = json.contains("hotspots") ? wholeNumber(json.at("hotspots"), "hotspots", 0, core::kMaxHotSpots) : 0;
    view.capHoles = flagAt(json, "cap_holes", false);
    view.colormap = textAt(json, "colormap");
    core::colormap(view.colormap);  // known
    const nlohmann::json& scale = objectAt(json, "scale");
    const nlohmann::json& range = scale.at("range");
    if (!range.is_array() || range.size() != 2) throw std::invalid_argument("'scale.range' must be [lo, hi]");
    view.scale.range = {finiteFloat(range[0], "scale.range"), finiteFloat(range[1], "scale.range")};
    view.scale.log = flagAt(scale, "log");
    view.scale.invert = flagAt(scale, "invert");
    if (!(view.scale.range.lo <= view.scale.range.hi) || (view.scale.log && !(view.scale.range.lo > 0.0f)))
        throw std::invalid_argument("'scale.range' must be ordered (and positive on a log scale)");
    view.units = textAt(json, "units", "");
    view.legend = !json.at("legend").is_null();
    if (view.legend) {
        if (!json.at("legend").is_string()) throw std::invalid_argument("'legend' must be a side's name or null");
        view.legendSide = core::legendSideFromName(json.at("legend").get<std::string>());
    }
    view.outline = flagAt(json, "outline");
    view.shadows = flagAt(json, "shadows");
    view.shadeIndirect = flagAt(json, "shade_indirect");
    view.samplesPerPixel = json.contains("spp") ? wholeNumber(json.at("spp"), "spp", 1, 1024) : 1;
    view.transparent = flagAt(json, "transparent", false);
    if (json.contains("mesh_units")) {
        const nlohmann::json& units = objectAt(json, "mesh_units");
        const nlohmann::json& centre = units.at("center");
        if (!centre.is_array() || centre.size() != 3)
            throw std::invalid_argument("'mesh_units.center' must be [x, y, z]");
        for (int k = 0; k < 3; ++k) {
            if (!centre[k].is_number() || !std::isfinite(centre[k].get<double>()))
                throw std::invalid_argument("'mesh_units.center' must be finite numbers");
            view.meshUnits.center[k] = centre[k].get<double>();
        }
        const nlohmann::json& scale = units.at("scale");
        if (!scale.is_number() || !(scale.get<double>() > 0.0) || !std::isfinite(scale.get<double>()))
            throw std::invalid_argument("'mesh_units.scale' must be a positive number");
        view.meshUnits.scale = scale.get<double>();
    }
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
    view.cellToPoint = load.read.cellToPoint;
    view.hotSpots = load.hotSpots;
    view.capHoles = load.capHoles;
    view.colormap = options.shading.colormap;
    view.scale = options.shading.scale;
    view.units = options.units;
    view.legend = options.legend;
    view.legendSide = options.legendSide;
    view.outline = options.outline;
    view.shadows = options.shading.shadows;
    view.shadeIndirect = options.shading.shadeIndirect;
    view.samplesPerPixel = options.samplesPerPixel;
    view.transparent = options.shading.transparentBackground;
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
            {"cell_to_point", view.cellToPoint},
            {"hotspots", view.hotSpots},
            {"cap_holes", view.capHoles},
            {"colormap", view.colormap},
            {"scale", {{"range", {view.scale.range.lo, view.scale.range.hi}}, {"log", view.scale.log}, {"invert", view.scale.invert}}},
            {"units", view.units},
            {"legend", view.legend ? nlohmann::json(sideName(view.legendSide)) : nlohmann::json()},
            {"outline", view.outline},
            {"shadows", view.shadows},
            {"shade_indirect", view.shadeIndirect},
            {"spp", view.samplesPerPixel},
            {"transparent", view.transparent},
            {"mesh_units", core::meshUnitsJson(view.meshUnits)}};
}

ViewFile readViewFile(const std::string& path)
{
    return detail::parseViewFile(path, core::detail::readFileBytes(path));  // a folder or pipe named, not read
}

ViewFile detail::parseViewFile(const std::string& path, const std::string& text)
{
    try {
        return viewFromJson(nlohmann::json::parse(text));
    } catch (const std::exception& e) {
        throw InputError(path + ": bad view file (" + core::jsonErrorWords(e) + ")");
    }
}

void writeViewFile(const ViewFile& view, const std::string& path) { writeJsonFile(viewToJson(view), path); }

}  // namespace ivis::app
