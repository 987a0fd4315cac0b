#include "json_output.h"

#include <ivis/core/atomic_file.h>

#include <fstream>
#include <stdexcept>

namespace ivis::app {

nlohmann::json methodParamsJson(const render::MethodParams& params)
{
    nlohmann::json json = {{"method", render::toString(params.method)}};
    switch (params.method) {
    case render::Method::InverseVis:
        json["alpha"] = params.curved.alpha;
        json["hull_offset"] = params.curved.hullOffset;
        json["step"] = params.curved.stepSize;
        break;
    case render::Method::InverseVisAdaptive:
        json["alpha_profile"] = params.profile.coefficients;
        json["hull_offset"] = params.curved.hullOffset;
        json["step"] = params.curved.stepSize;
        break;
    case render::Method::Mirror:
        json["mirror_w"] = params.mirror.w;
        json["mirror_distance_behind"] = params.mirror.distanceBehind;
        break;
    case render::Method::Neugebauer:
        json["ring_centre"] = {params.ring.centre.x, params.ring.centre.y, params.ring.centre.z};
        json["ring_width"] = params.ring.ringWidth;
        break;
    case render::Method::Front:
    case render::Method::Backfaces: break;
    }
    return json;
}

nlohmann::json visitedViewJson(const render::VisitedView& view)
{
    return {{"theta", view.thetaDeg},
            {"phi", view.phiDeg},
            {"energy", view.value.energy},
            {"front_energy", view.value.front},
            {"accepted", view.accepted},
            {"params", methodParamsJson(view.params)}};
}

void writeJsonFile(const nlohmann::json& json, const std::string& path)
{
    core::writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << json.dump(2) << "\n";
        if (!out) throw std::runtime_error("write failed");
    });
}

}  // namespace ivis::app
