#include "probe_report.h"

#include <ivis/core/errors.h>
#include <ivis/core/number_text.h>

#include <cmath>

namespace ivis::app {
namespace {

using core::shortNumber;

const char* regionName(render::Region region)
{
    switch (region) {
    case render::Region::Direct: return "direct";
    case render::Region::Indirect: return "indirect";
    case render::Region::Background: break;
    }
    return "background";
}

/// The file cell of the point's triangle; nullopt on a cap over a hole (core::capHoles).
std::optional<std::size_t> fileCell(const core::SurfaceField& field, int triangle)
{
    const std::size_t t = std::size_t(triangle);
    if (field.mesh.isCap(t)) return std::nullopt;
    return field.triangleCells.empty() ? t : std::size_t(field.triangleCells[t]);
}

/// "; its ray starts 0.57 across its ring at speed 2.3 (bend 0.41, stable_shift 0.8)", or for a ray
/// not drawn "; its ray from 0.91 across its ring at speed 2.48 is not drawn: its landing is unstable
/// (bend 1.37, stable_shift 0.8)" (a hull-exit seed has no ring, a seed refused unlaunched no speed).
std::string launchText(const ProbeReport& report)
{
    const render::ProbedLaunch& launch = *report.probe.launch;
    auto hundredths = [](float value) { return shortNumber(std::round(value * 100.0) / 100.0); };
    const std::string where = launch.ring ? " " + hundredths(*launch.ring) + " across its ring" : "";
    const std::string speed = launch.speed ? " at speed " + hundredths(*launch.speed) : "";
    std::string text = launch.refusal ? "; its ray" + (where.empty() ? "" : " from" + where) + speed +
                                            " is not drawn: " + launch.refusal
                                      : "; its ray starts" + where + speed;
    if (launch.bend > 0.0f && !report.ruleName.empty())
        text += " (bend " + shortNumber(std::round(launch.bend * 1000.0) / 1000.0) + ", " + report.ruleName + " " +
                shortNumber(report.rule) + ")";
    return text;
}

}  // namespace

glm::ivec2 parseProbePixel(const std::string& text, int width, int height)
{
    // Digits only, at most five (no sign, space or overflow): a picture is at most 32768 wide.
    auto coordinate = [](const std::string& digits, int& value) {
        if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos)
            return false;
        value = std::stoi(digits);
        return true;
    };
    const std::size_t comma = text.find(',');
    int x = 0, y = 0;
    if (comma == std::string::npos || !coordinate(text.substr(0, comma), x) || !coordinate(text.substr(comma + 1), y))
        throw InputError("--probe '" + text +
                         "': expected X,Y, a pixel of the picture from its top left (e.g. 512,130)");
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw InputError("--probe '" + text + "': outside the " + std::to_string(width) + "x" +
                         std::to_string(height) + " picture (X 0 to " + std::to_string(width - 1) + ", Y 0 to " +
                         std::to_string(height - 1) + ")");
    return {x, y};
}

ProbeReport probeReport(const render::RenderScene& scene, const render::MethodPtr& method,
                        const core::Camera& camera, int width, int height, const glm::ivec2& pixel,
                        const render::AdaptiveSampling& sampling)
{
    ProbeReport report;
    report.pixel = pixel;
    report.probe = render::probePixel(scene, method, camera, width, height, pixel.x + 0.5, pixel.y + 0.5, sampling);
    const render::SurfacePoint& point = report.probe.mapping.point;
    if (point.valid())
        report.view = render::facingView(scene.bvh(), point.position, point.triangle, report.probe.facing);
    report.ruleName = method->info().readableRuleParameter;
    if (!report.ruleName.empty()) report.rule = method->values().at(report.ruleName)[0];
    return report;
}

nlohmann::json probeJson(const ProbeReport& report, const core::SurfaceField& field)
{
    nlohmann::json json = {{"pixel", {report.pixel.x, report.pixel.y}},
                           {"region", regionName(report.probe.mapping.region)}};
    if (const std::optional<render::ProbedLaunch>& launch = report.probe.launch) {
        const glm::dvec3 seed = field.normalization.meshFromNormalized(glm::dvec3(launch->seed));
        json["launch"] = {{"seed", {seed.x, seed.y, seed.z}},
                          {"ring", launch->ring ? nlohmann::json(*launch->ring) : nlohmann::json()},
                          {"speed", launch->speed ? nlohmann::json(*launch->speed) : nlohmann::json()},
                          {"bend", launch->bend},
                          {"drawn", !launch->refusal},
                          {"refusal", launch->refusal ? nlohmann::json(launch->refusal) : nlohmann::json()}};
    }
    const render::SurfacePoint& point = report.probe.mapping.point;
    if (!point.valid()) return json;
    const glm::dvec3 position = field.normalization.meshFromNormalized(glm::dvec3(point.position));
    json["position"] = {position.x, position.y, position.z};
    const std::optional<std::size_t> cell = fileCell(field, point.triangle);
    json["cell"] = cell ? nlohmann::json(*cell) : nlohmann::json();
    json["scalar"] = std::isnan(report.probe.scalar) ? nlohmann::json() : nlohmann::json(report.probe.scalar);
    json["view"] = report.view ? nlohmann::json{{"theta", report.view->x}, {"phi", report.view->y}} : nlohmann::json();
    return json;
}

std::string probeLine(const ProbeReport& report, const core::SurfaceField& field)
{
    std::string line = "pixel " + std::to_string(report.pixel.x) + "," + std::to_string(report.pixel.y) + ": " +
                       regionName(report.probe.mapping.region);
    const render::SurfacePoint& point = report.probe.mapping.point;
    if (!point.valid()) return report.probe.launch ? line + launchText(report) : line;
    if (field.hasScalar())
        line += ", " + field.name + " " +
                (std::isnan(report.probe.scalar) ? std::string("none (NaN or a cap)") : shortNumber(report.probe.scalar));
    const glm::dvec3 p = field.normalization.meshFromNormalized(glm::dvec3(point.position));
    line += " at (" + shortNumber(p.x) + ", " + shortNumber(p.y) + ", " + shortNumber(p.z) + ")";
    const std::optional<std::size_t> cell = fileCell(field, point.triangle);
    line += cell ? ", cell " + std::to_string(*cell) : ", on a cap over a hole";
    line += report.view ? "; seen directly from --theta " + shortNumber(std::round(report.view->x * 10.0) / 10.0) +
                              " --phi " + shortNumber(std::round(report.view->y * 10.0) / 10.0)
                        : "; no view from outside sees it directly";
    return report.probe.launch ? line + launchText(report) : line;
}

}  // namespace ivis::app
