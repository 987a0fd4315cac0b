#include "viewer_panel.h"

#include <ivis/core/colormap.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace ivis::app {
namespace {

/// Sliders of the curved rays' hull offset (below the volume's @a reach), step and max steps; true when changed.
bool curvedRaySliders(render::CurvedRayParams& curved, float reach)
{
    bool changed = ImGui::SliderFloat("hull offset", &curved.hullOffset, 0.05f, 0.98f * reach, "%.3f");
    tooltip("phi0: the hull {phi = phi0} the curved rays start from; below the volume's reach");
    changed |= ImGui::SliderFloat("step h", &curved.stepSize, 0.01f, 0.5f, "%.3f");
    changed |= ImGui::SliderInt("max steps", &curved.maxSteps, 10, 4000);
    return changed;
}

/// Sliders of the adaptive InverseVis's profile coefficients a0, a1, a2; true when changed.
bool profileSliders(render::AlphaProfile& profile)
{
    char help[200];
    std::snprintf(help, sizeof help,
                  "alpha(c) = a0 + a1 c + a2 c^2, clamped to [0, %.1f]; c = r . grad phi / |grad phi| at the hull "
                  "seed (0 where the view ray grazes the hull, growing toward the silhouette)",
                  profile.maxAlpha);
    bool changed = false;
    for (int i = 0; i < 3; ++i) {
        const std::string label = "a" + std::to_string(i);
        changed |= ImGui::SliderFloat(label.c_str(), &profile.coefficients[std::size_t(i)], -2.0f, 6.0f, "%.3f");
        tooltip(help);
    }
    return changed;
}

}  // namespace

void tooltip(const char* text)
{
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::TextUnformatted(text);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

bool methodWidgets(render::MethodParams& params, float reach)
{
    bool changed = false;
    const std::vector<std::string> methods = render::methodNames();
    int method = int(params.method);
    if (ImGui::BeginCombo("method", methods[std::size_t(method)].c_str())) {
        for (int i = 0; i < int(methods.size()); ++i)
            if (ImGui::Selectable(methods[std::size_t(i)].c_str(), i == method)) {
                params.method = render::Method(i);
                changed = true;
            }
        ImGui::EndCombo();
    }
    switch (params.method) {
    case render::Method::InverseVis:
        changed |= ImGui::SliderFloat("alpha", &params.curved.alpha, 0.0f, 4.0f, "%.3f");
        changed |= curvedRaySliders(params.curved, reach);
        break;
    case render::Method::InverseVisAdaptive:
        changed |= profileSliders(params.profile);
        changed |= curvedRaySliders(params.curved, reach);
        break;
    case render::Method::Mirror:
        for (int i = 0; i < 5; ++i) {
            const std::string label = "w" + std::to_string(i + 1);
            changed |= ImGui::SliderFloat(label.c_str(), &params.mirror.w[std::size_t(i)], -1.0f, 1.0f, "%.3f");
        }
        changed |= ImGui::SliderFloat("behind", &params.mirror.distanceBehind, 0.0f, 3.0f, "%.2f");
        break;
    case render::Method::Neugebauer:
        changed |= ImGui::SliderFloat("ring width", &params.ring.ringWidth, 0.05f, 0.8f, "%.2f");
        changed |= ImGui::DragFloat3("centre", &params.ring.centre.x, 0.01f, -1.0f, 1.0f, "%.2f");
        break;
    default: break;
    }
    return changed;
}

bool lookWidgets(render::ShadingOptions& shading, int& colormapIndex, const core::ScalarRange& dataRange,
                 bool hasScalar, float& renderScale)
{
    bool changed = false;
    const std::vector<std::string> maps = core::colormapNames();
    if (ImGui::BeginCombo("colour map", maps[std::size_t(std::clamp(colormapIndex, 0, int(maps.size()) - 1))].c_str())) {
        for (int i = 0; i < int(maps.size()); ++i)
            if (ImGui::Selectable(maps[std::size_t(i)].c_str(), i == colormapIndex)) {
                colormapIndex = i;
                shading.colormap = maps[std::size_t(i)];
                changed = true;
            }
        ImGui::EndCombo();
    }
    if (hasScalar) {
        const float speed = std::max(1e-6f, (dataRange.hi - dataRange.lo) / 300.0f);
        float lo = shading.range.lo, hi = shading.range.hi;
        if (ImGui::DragFloatRange2("range", &lo, &hi, speed, 0.0f, 0.0f, "%.4g", "%.4g")) {
            if (lo < hi) {
                shading.range = {lo, hi};
                changed = true;
            }
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("data")) {
            shading.range = dataRange;
            changed = true;
        }
        tooltip("reset the range to the data's minimum and maximum");
    }
    changed |= ImGui::Checkbox("shadows", &shading.shadows);
    changed |= ImGui::SliderFloat("render scale", &renderScale, 0.25f, 1.0f, "%.2f");
    tooltip("fraction of the window's pixels traced (software OpenGL starts at 0.5)");
    return changed;
}

void optimiserWidgets(OptimiserSettings& settings, bool hasScalar)
{
    const std::vector<std::string> energies = {"visibility", "scalar"};
    const bool scalar = settings.optimization.energy == "scalar";
    if (ImGui::BeginCombo("energy", settings.optimization.energy.c_str())) {
        for (const std::string& name : energies)
            if ((name != "scalar" || hasScalar) &&
                ImGui::Selectable(name.c_str(), name == settings.optimization.energy))
                settings.optimization.energy = name;
        ImGui::EndCombo();
    }
    tooltip(scalar ? "scalar: sum of the normalised scalar over the pixels that show the surface (METHOD.md)"
                   : "visibility: fraction of the surface voxels some ray lands in (METHOD.md, the paper's Table 1)");
    ImGui::SliderInt("opt. rays", &settings.resolution, 16, 400);
    tooltip("rays per image side while optimising (paper: 100 or 1000)");
    ImGui::SliderInt("anneal steps", &settings.optimization.steps, 1, 100);
    tooltip("proposals of the simulated annealing after the start view");
}

const char* optimiseLabel(render::Method method)
{
    if (method == render::Method::Mirror) return "optimise w";
    return method == render::Method::InverseVisAdaptive ? "optimise profile" : "optimise alpha";
}

}  // namespace ivis::app
