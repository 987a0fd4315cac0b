// ViewerApp: mouse and keys: orbit, pan, zoom, probe, shortcuts; turning the camera to a view.
#include "viewer_app.h"

#include "viewer_clock.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

namespace ivis::app {

void ViewerApp::handleInput()
{
    ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureMouse) {
        const bool pan = io.MouseDown[1] || io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift);
        if ((io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) && (io.MouseDown[0] || pan)) {
            mAnimation.stop();
            int width = 0, height = 0;
            glfwGetWindowSize(mWindow, &width, &height);
            if (pan) mOrbit.pan(io.MouseDelta.x, io.MouseDelta.y, height);
            else mOrbit.orbit(io.MouseDelta.x, io.MouseDelta.y);
            mInteraction.moved(now(), true);
            mDirty = true;
        }
        if (io.MouseWheel != 0.0f) {
            mAnimation.stop();
            mOrbit.zoom(io.MouseWheel);
            mInteraction.moved(now(), false);
            mDirty = true;
        }
        // A click (released within 3 pixels of where it was pressed) probes the pixel under it.
        if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f && !io.KeyShift) {
            int fbWidth = 0, fbHeight = 0;
            glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
            const int x = int(std::floor(io.MousePos.x * io.DisplayFramebufferScale.x)) - mPicture.x;
            const int y = int(std::floor(io.MousePos.y * io.DisplayFramebufferScale.y)) -
                          (fbHeight - mPicture.y - mPicture.height);
            if (x >= 0 && y >= 0 && x < mPicture.width && y < mPicture.height) probeAt({x, y});
        }
    }
    if (!io.MouseDown[0] && !io.MouseDown[1] && !io.MouseDown[2]) mInteraction.released();
    if (!io.WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) takeNumberedScreenshot();
        if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) {
            mAnimation.stop();
            mOrbit.frameAgain();
            mDirty = true;
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(mWindow, GLFW_TRUE);
        if (mSeries && !jobRunning()) {
            if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT) && mStep + 1 < mSeries->steps().size()) switchStep(mStep + 1);
            if (ImGui::IsKeyPressed(GLFW_KEY_LEFT) && mStep > 0) switchStep(mStep - 1);
        }
        if (mSeries && (mPlaying || !jobRunning()) && ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) setPlaying(!mPlaying);
    }
}

void ViewerApp::probeAt(const glm::ivec2& pixel)
{
    if (!mLoaded) {
        mStatus = "probe: the volume is still loading";
        return;
    }
    const std::string line =
        mProbe.probe(*mLoaded->scene, mMethod, mOrbit.camera(), mPicture.width, mPicture.height, pixel);
    std::printf("inversevis-view: %s\n", line.c_str());
    std::fflush(stdout);
}

void ViewerApp::turnTo(const glm::dvec2& view)
{
    OrbitCamera from = mOrbit;
    from.framed = true;  // framed on the way, as it ends
    OrbitCamera to = from;
    to.frameAgain();
    to.thetaDeg = view.x;
    to.phiDeg = view.y;
    mAnimation = CameraAnimation(from, {}, to, {}, now(), 1.0);
    mDirty = true;
}

}  // namespace ivis::app
