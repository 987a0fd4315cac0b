/// @file probe_report.h
/// @brief What a pixel of a picture shows, as `render --probe` and a click in the viewer tell it:
///        its region, the surface point in the mesh's own units, the file cell, the scalar there,
///        and the --theta / --phi of a view that shows the point directly.
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/method.h>
#include <ivis/render/pixel_probe.h>
#include <ivis/render/render_scene.h>

#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace ivis::app {

/// @brief One pixel probed.
struct ProbeReport {
    glm::ivec2 pixel{0};             ///< column and row of the picture, from its top left
    render::PixelProbe probe;        ///< what the pixel's centre shows
    std::optional<glm::dvec2> view;  ///< theta and phi (degrees) of a view that sees the point head-on (facingView)
    std::string ruleName;            ///< the method's rule for drawing rays (MethodInfo::readableRuleParameter; "" for none)
    float rule = 0.0f;               ///< its value
};

/// @brief Parses --probe's "X,Y", a pixel of a @a width x @a height picture.
/// @throw InputError "--probe 'X,Y': ..." for another form or a pixel outside the picture
glm::ivec2 parseProbePixel(const std::string& text, int width, int height);

/// @brief Probes the centre of @a pixel of a @a width x @a height picture of @a method from
///        @a camera, and finds the view that sees its point head-on.
ProbeReport probeReport(const render::RenderScene& scene, const render::MethodPtr& method,
                        const core::Camera& camera, int width, int height, const glm::ivec2& pixel,
                        const render::AdaptiveSampling& sampling = {});

/// @brief {"pixel", "region" ("background", "direct", "indirect"), for a point: "position"
///        (mesh units), "cell" (the file's cell; null on a cap over a hole), "scalar" (null for
///        none), "view" ({"theta", "phi"} or null), and for a curved ray's pixel: "launch" ({"seed"
///        (mesh units), "ring" (null but for closest-approach seeds), "speed" (null for a seed
///        refused before its launch), "bend", "drawn", "refusal" (why not drawn; null when drawn)})}.
nlohmann::json probeJson(const ProbeReport& report, const core::SurfaceField& field);

/// @brief One line, e.g. "pixel 512,130: indirect, pressure_t200 0.613 at (12.1, -4.5, 6.7), cell 4711;
///        seen directly from --theta 112.4 --phi -40.2; its ray starts 0.57 across its ring at speed
///        2.3 (bend 0.41, stable_shift 0.8)" (the position in the mesh's own units); a background
///        pixel whose ray is not drawn says why.
std::string probeLine(const ProbeReport& report, const core::SurfaceField& field);

}  // namespace ivis::app
