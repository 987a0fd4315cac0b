/// @file viewer_panel.h
/// @brief The widgets of the viewer's Dear ImGui panel: the method and its parameters, the look,
///        the optimiser's settings.
/// @note Call between ImGui::Begin and ImGui::End of the panel, on the main thread.
#pragma once

#include "view_optimiser.h"

#include <ivis/core/colormap.h>
#include <ivis/render/method.h>
#include <ivis/render/shading.h>

#include <string>

namespace ivis::app {

/// @brief Shows @a text as the tooltip of the last widget while it is hovered (even disabled).
void tooltip(const char* text);

/// @brief The method combo and a widget per parameter of the chosen method, within the bounds its
///        description gives (its tracing accuracy folded under "tracing"); true when anything changed.
/// @param reach the volume's reach: the curved rays' hull offset stays below it
bool methodWidgets(render::MethodPtr& method, float reach);

/// @brief Colour map, scalar range, log and invert (when @a hasScalar; "data" resets the scale to
///        @a dataScale) and shadows; true when anything changed.
/// @param colormapIndex index of shading.colormap in core::colormapNames(), kept in step with it
bool lookWidgets(render::ShadingOptions& shading, int& colormapIndex, const core::ColorScale& dataScale,
                 bool hasScalar);

/// @brief Render scale and interaction scale; true when the render scale changed (the interaction
///        scale changes no picture at rest).
bool traceScaleWidgets(float& renderScale, float& interactionScale);

/// @brief Energy (scalar only when @a hasScalar), optimisation rays and annealing steps.
void optimiserWidgets(OptimiserSettings& settings, bool hasScalar);

/// @brief Label of the parameter optimiser's button: "optimise" and the optimised parameters.
std::string optimiseLabel(const render::Method& method);

}  // namespace ivis::app
