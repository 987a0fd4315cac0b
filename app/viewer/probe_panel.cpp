#include "probe_panel.h"

#include <ivis/render/pixel_probe.h>
#include <ivis/render/surface_point.h>

#include <glm/geometric.hpp>

#include <imgui.h>

namespace ivis::app {

std::string ProbePanel::probe(const render::RenderScene& scene, const render::MethodPtr& method,
                              const core::Camera& camera, int width, int height, const glm::ivec2& pixel)
{
    mReport = probeReport(scene, method, camera, width, height, pixel);
    mCamera = camera;
    mMethod = method;
    mPictureSize = {width, height};
    return probeLine(*mReport, scene.field());
}

void ProbePanel::readScalar(const core::SurfaceField& field)
{
    if (mReport) mReport->probe.scalar = render::scalarAt(field, mReport->probe.mapping.point);
}

std::optional<glm::dvec2> ProbePanel::widgets(const core::SurfaceField& field)
{
    ImGui::TextUnformatted("probe: click the picture");
    if (!mReport) return std::nullopt;
    ImGui::TextWrapped("%s", probeLine(*mReport, field).c_str());
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
    const core::CameraFrame frame(camera, picture.width, picture.height);
    const glm::dvec3 position(point.position);
    // The line of sight: from the eye, or along the view for an orthographic camera.
    const glm::dvec3 from = camera.orthographic ? position - 10.0 * frame.forward() : camera.eye;
    const bool inFront = glm::dot(position - camera.eye, frame.forward()) > 0.0;
    glm::dvec2 at;  // in the picture's pixels, from its top left
    if ((inFront || camera.orthographic) && render::seenDirectly(scene.bvh(), from, point.position, point.triangle)) {
        at = frame.project(position);
    } else {
        const bool sameView = method == mMethod && camera.eye == mCamera.eye && camera.target == mCamera.target &&
                              camera.fovYDeg == mCamera.fovYDeg && camera.orthoHalfHeight == mCamera.orthoHalfHeight &&
                              camera.windowCentre == mCamera.windowCentre &&
                              glm::ivec2(picture.width, picture.height) == mPictureSize;
        if (!sameView) return;
        at = glm::dvec2(mReport->pixel) + 0.5;
    }
    if (at.x < 0.0 || at.y < 0.0 || at.x >= picture.width || at.y >= picture.height) return;
    const float top = float(framebufferHeight - picture.y - picture.height);
    const ImVec2 centre((float(picture.x) + float(at.x)) / framebufferScale.x,
                        (top + float(at.y)) / framebufferScale.y);
    drawList.AddCircle(centre, 9.0f, IM_COL32(255, 255, 255, 255), 24, 4.0f);
    drawList.AddCircle(centre, 9.0f, IM_COL32(220, 30, 30, 255), 24, 2.0f);
}

}  // namespace ivis::app
