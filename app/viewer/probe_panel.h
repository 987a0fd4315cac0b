/// @file probe_panel.h
/// @brief The viewer's probe: a click on the picture tells what that pixel shows (the panel's
///        "probe" lines, as `render --probe` prints them), "turn to it" eases the camera to a view
///        that shows the point directly, and a ring marks the point wherever the picture shows it.
/// @note Call on the main thread; widgets() between ImGui::Begin and ImGui::End of the panel.
#pragma once

#include "color_bar_overlay.h"
#include "../probe_report.h"

#include <ivis/core/camera.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/method.h>
#include <ivis/render/render_scene.h>

#include <glm/vec2.hpp>

#include <optional>
#include <string>

struct ImDrawList;

namespace ivis::app {

/// @brief The last pixel probed, and where its point lies.
class ProbePanel {
public:
    /// @brief Probes @a pixel of a @a width x @a height picture of @a method from @a camera (the
    ///        frame shown) and keeps the report; returns its line.
    std::string probe(const render::RenderScene& scene, const render::MethodPtr& method, const core::Camera& camera,
                      int width, int height, const glm::ivec2& pixel);
    /// @brief Forgets the probe (the mesh shown changed).
    void clear() { mReport.reset(); }
    /// @brief Reads the probed point's scalar again from @a field (a time step of the same mesh).
    void readScalar(const core::SurfaceField& field);
    /// @brief The probe's lines and its "turn to it" button; the angles (theta, phi) to turn to
    ///        when the button was pressed.
    std::optional<glm::dvec2> widgets(const core::SurfaceField& field);
    /// @brief Marks the probed point on @a drawList: at its place in the picture of @a camera when
    ///        its straight line of sight is clear, else at the probed pixel while the camera, the
    ///        method and the picture's size are those of the click; nothing otherwise.
    /// @param picture where the picture lies in the framebuffer (OpenGL coordinates)
    /// @param framebufferScale framebuffer pixels per window coordinate
    void drawMarker(ImDrawList& drawList, const render::RenderScene& scene, const render::MethodPtr& method,
                    const core::Camera& camera, const PictureViewport& picture, int framebufferHeight,
                    const glm::vec2& framebufferScale) const;

private:
    std::optional<ProbeReport> mReport;
    core::Camera mCamera;           ///< the camera of the probed picture
    render::MethodPtr mMethod;      ///< the method of the probed picture
    glm::ivec2 mPictureSize{0};     ///< the probed picture's size
};

}  // namespace ivis::app
