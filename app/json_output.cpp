#include "json_output.h"

#include <ivis/core/atomic_file.h>
#include <ivis/render/method_json.h>

#include <fstream>
#include <stdexcept>

namespace ivis::app {

nlohmann::json visitedViewJson(const optimize::VisitedView& view)
{
    return {{"theta", view.thetaDeg},
            {"phi", view.phiDeg},
            {"fov_y_deg", view.camera.fovYDeg},
            {"energy", view.value.energy},
            {"front_energy", view.value.front},
            {"accepted", view.accepted},
            {"params", render::methodToJson(*view.method)}};
}

nlohmann::json measuresJson(const optimize::EnergyValue& value, double coherence, bool withReveal)
{
    nlohmann::json json = {{"visibility", value.energy},
                           {"paper_literal", value.paperLiteral},
                           {"front_visibility", value.front},
                           {"coherence", coherence}};
    if (withReveal)
        json["reveal"] = {{"total", value.reveal.total}, {"direct", value.reveal.direct}, {"per_region", value.reveal.perRegion}};
    return json;
}

void writeTextFile(const std::string& text, const std::string& path)
{
    core::writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << text;
        if (!out) throw std::runtime_error("write failed");
    });
}

void writeJsonFile(const nlohmann::json& json, const std::string& path) { writeTextFile(json.dump(2) + "\n", path); }

}  // namespace ivis::app
