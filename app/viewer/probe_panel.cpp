#include "probe_panel.h"

#include <ivis/render/pixel_probe.h>

#include <imgui.h>

#include <cstdio>

namespace ivis::app {

std::string ProbePanel::probe(const render::RenderScene& scene, const render::MethodPtr& method,
                              const core::Camera& camera, int width, int height, const glm::ivec2& pixel)
{
    mReport = probeReport(scene, method, camera, width, height, pixel);
    mCamera = camera;
    mMethod = method;
    mSize = {width, height};
    return probeLine(*mReport, scene.field());
}

std::optional<glm::dvec2> ProbePanel::widgets(const core::SurfaceField& field)
{
    ImGui::TextUnformatted("probe: click the picture");
    if (!mReport) return std::nullopt;
    ImGui::TextUnformatted(probeLine(*mReport, field).c_str());
    if (!mReport->view) return std::nullopt;
    const bool pressed = ImGui::Button("turn to it");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("ease the camera to the view that shows the probed point directly and most nearly head-on "
                          "(render::facingView), framed");
    return pressed ? mReport->view : std::nullopt;
}

void ProbePanel::drawMarker(ImDrawList& drawList, const render::RenderScene& scene, const render::MethodPtr& method,
                            const core::Camera& camera, const PictureViewport& picture, int framebufferHeight,
                            const glm::vec2& framebufferScale) const
{
    if (!mReport || !mReport->probe.mapping.point.valid() || picture.width <= 0 || picture.height <= 0) return;
    const render::SurfacePoint& point = mReport->probe.mapping.point;
    glm::dvec2 at;  // in the picture's pixels, from its top left
    if (render::seenDirectly(scene.bvh(), camera.eye, point.position, point.triangle)) {
        at = core::CameraFrame(camera, picture.width, picture.height).project(glm::dvec3(point.position));
    } else {
        const bool sameView = method == mMethod && camera.eye == mCamera.eye && camera.target == mCamera.target &&
                              camera.fovYDeg == mCamera.fovYDeg && camera.windowCentre == mCamera.windowCentre;
        if (!sameView) return;
        at = (glm::dvec2(mReport->pixel) + 0.5) * glm::dvec2(picture.width, picture.height) / glm::dvec2(mSize);
    }
    if (at.x < 0.0 || at.y < 0.0 || at.x >= picture.width || at.y >= picture.height) return;
    const float top = float(framebufferHeight - picture.y - picture.height);
    const ImVec2 centre((float(picture.x) + float(at.x)) / framebufferScale.x, (top + float(at.y)) / framebufferScale.y);
    drawList.AddCircle(centre, 9.0f, IM_COL32(255, 255, 255, 255), 24, 4.0f);
    drawList.AddCircle(centre, 9.0f, IM_COL32(220, 30, 30, 255), 24, 2.0f);
}

}  // namespace ivis::app
