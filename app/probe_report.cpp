#include "probe_report.h"

#include <ivis/core/errors.h>

#include <cmath>
#include <cstdio>

namespace ivis::app {
namespace {

/// A number as a reader wants it: six significant digits.
std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

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

}  // namespace

glm::ivec2 parseProbePixel(const std::string& text, int width, int height)
{
    int x = 0, y = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &extra) != 2)
        throw InputError("--probe '" + text + "': expected X,Y, a pixel of the picture from its top left (e.g. 512,130)");
    if (x < 0 || y < 0 || x >= width || y >= height)
        throw InputError("--probe '" + text + "': outside the " + std::to_string(width) + "x" + std::to_string(height) +
                         " picture (X 0 to " + std::to_string(width - 1) + ", Y 0 to " + std::to_string(height - 1) + ")");
    return {x, y};
}

ProbeReport probeReport(const render::RenderScene& scene, const render::MethodPtr& method,
                        const core::Camera& camera, int width, int height, const glm::ivec2& pixel)
{
    ProbeReport report;
    report.pixel = pixel;
    report.probe = render::probePixel(scene, method, camera, width, height, pixel.x + 0.5, pixel.y + 0.5);
    const render::SurfacePoint& point = report.probe.mapping.point;
    if (point.valid()) report.view = render::facingView(scene.bvh(), point.position, point.triangle, report.probe.facing);
    return report;
}

nlohmann::json probeJson(const ProbeReport& report, const core::SurfaceField& field)
{
    nlohmann::json json = {{"pixel", {report.pixel.x, report.pixel.y}},
                           {"region", regionName(report.probe.mapping.region)}};
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
    if (!point.valid()) return line;
    if (field.hasScalar())
        line += ", " + field.name + " " +
                (std::isnan(report.probe.scalar) ? std::string("none (NaN or a cap)") : number(report.probe.scalar));
    const glm::dvec3 p = field.normalization.meshFromNormalized(glm::dvec3(point.position));
    line += " at (" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
    const std::optional<std::size_t> cell = fileCell(field, point.triangle);
    line += cell ? ", cell " + std::to_string(*cell) : ", on a cap over a hole";
    line += report.view ? "; seen directly from --theta " + number(std::round(report.view->x * 10.0) / 10.0) +
                              " --phi " + number(std::round(report.view->y * 10.0) / 10.0)
                        : "; no view from outside sees it directly";
    return line;
}

}  // namespace ivis::app
