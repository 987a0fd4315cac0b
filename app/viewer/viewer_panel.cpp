#include "viewer_panel.h"

#include <ivis/core/colormap.h>
#include <ivis/render/method_registry.h>

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace ivis::app {
namespace {

/// The most of the volume's reach a distance parameter (the hull offset) may take in the panel.
constexpr float kReachShare = 0.98f;

/// The key with '_' shown as a space ("alpha_profile" -> "alpha profile").
std::string labelOf(const std::string& key)
{
    std::string label = key;
    std::replace(label.begin(), label.end(), '_', ' ');
    return label;
}

/// A drag widget for one parameter within its bounds (and below @a reach where it must be); true when changed.
bool parameterWidget(const render::ParameterSpec& spec, std::vector<float>& values, float reach)
{
    const std::string label = labelOf(spec.key);
    const float hi = spec.belowReach ? std::min(spec.hi, kReachShare * reach) : spec.hi;
    const float speed = std::max(1e-4f, (std::min(hi, 10.0f) - std::max(spec.lo, -10.0f)) / 500.0f);
    bool changed = false;
    if (spec.integer) {
        std::vector<int> whole(values.begin(), values.end());
        const int lo = int(spec.lo), top = int(hi);
        changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_S32, whole.data(), int(whole.size()),
                                     std::max(1.0f, speed), &lo, &top, "%d", ImGuiSliderFlags_AlwaysClamp);
        values.assign(whole.begin(), whole.end());
    } else {
        changed = ImGui::DragScalarN(label.c_str(), ImGuiDataType_Float, values.data(), int(values.size()), speed,
                                     &spec.lo, &hi, "%.3f", ImGuiSliderFlags_AlwaysClamp);
    }
    tooltip(spec.help.c_str());
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

bool methodWidgets(render::MethodPtr& method, float reach)
{
    bool changed = false;
    if (ImGui::BeginCombo("method", method->name().c_str())) {
        for (const render::MethodInfo* info : render::methodRegistry())
            if (ImGui::Selectable(info->name.c_str(), info->name == method->name()) && info->name != method->name()) {
                // The new method keeps the values the user set of the parameters it shares (e.g. the
                // hull offset); the others take its own defaults (the wrap's hull is wider), within
                // the loaded volume's reach.
                render::ParameterValues shared;
                for (const auto& [key, values] : method->values())
                    if (info->parameter(key) && values != method->info().parameter(key)->defaults) shared[key] = values;
                for (const render::ParameterSpec& spec : info->parameters)
                    if (spec.belowReach && !shared.count(spec.key) && spec.defaults[0] > kReachShare * reach)
                        shared[spec.key] = {kReachShare * reach};
                method = render::makeMethod(info->name, shared);
                changed = true;
            }
        ImGui::EndCombo();
    }
    tooltip(method->info().help.c_str());
    render::ParameterValues values = method->values();
    bool edited = false, tracing = false;
    for (const render::ParameterSpec& spec : method->info().parameters) {
        if (spec.tracing) tracing = true;
        else edited |= parameterWidget(spec, values[spec.key], reach);
    }
    if (tracing && ImGui::TreeNode("tracing")) {
        for (const render::ParameterSpec& spec : method->info().parameters)
            if (spec.tracing) edited |= parameterWidget(spec, values[spec.key], reach);
        ImGui::TreePop();
    }
    if (edited) method = render::makeMethod(method->name(), values);
    return changed || edited;
}

bool lookWidgets(render::ShadingOptions& shading, int& colormapIndex, const core::ColorScale& dataScale,
                 bool hasScalar)
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
        core::ColorScale& scale = shading.scale;
        const float speed = std::max(1e-6f, (dataScale.range.hi - dataScale.range.lo) / 300.0f);
        float lo = scale.range.lo, hi = scale.range.hi;
        if (ImGui::DragFloatRange2("range", &lo, &hi, speed, 0.0f, 0.0f, "%.4g", "%.4g")) {
            if (lo < hi && (!scale.log || lo > 0.0f)) {
                scale.range = {lo, hi};
                changed = true;
            }
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("data")) {
            scale = dataScale;
            changed = true;
        }
        tooltip("reset the scale to the data's (as the command line's range options give it)");
        bool log = scale.log;
        if (ImGui::Checkbox("log", &log) && (!log || scale.range.hi > 0.0f)) {
            scale.log = log;
            if (log && scale.range.lo <= 0.0f) scale.range.lo = scale.range.hi / 1000.0f;  // a positive low end
            changed = true;
        }
        tooltip("logarithmic colour scale (a range ending at or below 0 starts at hi / 1000)");
        ImGui::SameLine();
        changed |= ImGui::Checkbox("invert", &scale.invert);
    }
    changed |= ImGui::Checkbox("shadows", &shading.shadows);
    tooltip("soft shadows of the key light, traced through the distance field (render --no-shadows turns them off)");
    return changed;
}

bool traceScaleWidgets(float& renderScale, float& interactionScale)
{
    const bool changed = ImGui::SliderFloat("render scale", &renderScale, 0.25f, 1.0f, "%.2f");
    tooltip("fraction of the window's pixels traced (software OpenGL starts at 0.5)");
    ImGui::SliderFloat("interaction scale", &interactionScale, 0.25f, 1.0f, "%.2f");
    tooltip("fraction of the render scale traced while you orbit, pan or zoom; the full picture follows when the "
            "camera rests (1: always the full render scale; software OpenGL starts at 0.5)");
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
    tooltip(scalar ? "scalar: sum of the normalised scalar over the pixels that show the surface (docs/method.md)"
                   : "visibility: fraction of the surface voxels some ray lands in (docs/measures.md, the paper's Table 1)");
    ImGui::SliderInt("opt. rays", &settings.resolution, 16, 400);
    tooltip("rays per image side while optimising (paper: 100 or 1000)");
    ImGui::SliderInt("anneal steps", &settings.optimization.steps, 1, 100);
    tooltip("proposals of the simulated annealing after the start view");
    ImGui::SliderInt("views", &settings.views, 1, 4);
    tooltip("'optimise view' also chooses the visited views that show the most surface with the best one (as "
            "optimize --views; visibility energy); the buttons 'view 1', 'view 2', ... then switch between them");
}

std::string optimiseLabel(const render::Method& method)
{
    std::string label = "optimise";
    for (const render::ParameterSpec& spec : method.info().parameters)
        if (spec.optimised) label += " " + labelOf(spec.key);
    return label;
}

}  // namespace ivis::app
