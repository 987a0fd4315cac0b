#include "viewer_app.h"

#include "../mesh_options.h"

#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/surface_point.h>

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <thread>

namespace ivis::app {
namespace {

std::string gLastGlfwError;

void onGlfwError(int code, const char* description)
{
    gLastGlfwError = std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

double now() { return glfwGetTime(); }

/// Milliseconds taken by @a work, waiting for the GPU to finish.
template <typename Work>
double timedMs(Work&& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

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

/// Label of the parameter optimiser's button for @a method.
const char* optimiseLabel(render::Method method)
{
    if (method == render::Method::Mirror) return "optimise w";
    return method == render::Method::InverseVisAdaptive ? "optimise profile" : "optimise alpha";
}

}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, core::SurfaceField field)
    : mOptions(options),
      mField(std::make_unique<core::SurfaceField>(std::move(field)))
{
    mOptions.view.resolution = std::to_string(options.width) + "x" + std::to_string(options.height);
    const render::RenderOptions render = mOptions.view.renderOptions(*mField);
    mMethod = render.method;
    mShading = render.shading;
    mDataRange = core::scalarRangeFromData(mField->values);
    mOptimiser.optimization = mOptions.optimization;
    mOptimiser.resolution = mOptions.optResolution;
    mOptions.optimization.energyOptions(mOptions.optResolution, mShading.range);  // validates --energy
    mOrbit = OrbitCamera::fromCamera(mOptions.view.camera(), !mOptions.view.cameraFile.empty());
    const std::vector<std::string> names = core::colormapNames();
    mColormapIndex = int(std::find(names.begin(), names.end(), mShading.colormap) - names.begin());
}

ViewerApp::~ViewerApp()
{
    mCancelJob = true;
    if (mJob.valid() && mJob.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        std::printf("inversevis-view: waiting for the running optimisation to finish (it cannot be interrupted)\n");
        std::fflush(stdout);
        mJob.wait();
    }
    mLoader.reset();  // cancels and joins
    closeWindow();
}

void ViewerApp::openWindow()
{
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw GlError("cannot open a window: " + gLastGlfwError + " (no display? headless use: xvfb-run -a ...)");
    mGlfwReady = true;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, mOptions.screenshot.empty() ? GLFW_TRUE : GLFW_FALSE);
    const std::string title = "inversevis-view: " + core::sourceStem(mOptions.mesh.source);
    mWindow = glfwCreateWindow(mOptions.width, mOptions.height, title.c_str(), nullptr, nullptr);
    if (!mWindow) throw GlError("OpenGL 4.3 core profile is not available: " + gLastGlfwError);
    glfwMakeContextCurrent(mWindow);
    if (epoxy_gl_version() < 43)
        throw GlError("OpenGL 4.3 core profile is not available (the context reports " +
                      std::to_string(epoxy_gl_version() / 10) + "." + std::to_string(epoxy_gl_version() % 10) + ")");
    glfwSwapInterval(mOptions.headless() ? 0 : 1);
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    mGlRenderer = std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
    mRenderer = std::make_unique<GpuRenderer>();
    mRenderer->setMesh(*mField, render::vertexNormals(mField->mesh));
    mRenderer->setColormap(mShading.colormap);
    // Software rasterisers trace every pixel on the CPU: start at half resolution there.
    if (mGlRenderer.find("llvmpipe") != std::string::npos || mGlRenderer.find("softpipe") != std::string::npos)
        mRenderScale = 0.5f;
    if (!mOptions.headless()) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(mWindow, true);
        ImGui_ImplOpenGL3_Init("#version 430 core");
        mImGuiReady = true;
    }
}

void ViewerApp::closeWindow()
{
    if (mImGuiReady) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        mImGuiReady = false;
    }
    mRenderer.reset();  // GL objects go before their context
    if (mWindow) glfwDestroyWindow(mWindow);
    mWindow = nullptr;
    if (mGlfwReady) glfwTerminate();
    mGlfwReady = false;
}

void ViewerApp::startLoading()
{
    const vdb::VolumeOptions volumeOptions = mOptions.mesh.volumeOptions();
    const std::string cachePath =
        defaultVolumePath(mOptions.resolvedCacheDir(), mOptions.mesh.source, volumeOptions.resolution);
    DenseSliceOptions slices;
    slices.budgetBytes = std::size_t(mOptions.textureBudgetMiB) << 20;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    slices.maxTextureSize = std::max(16, int(maxSize));
    mLoader = std::make_unique<SceneLoader>(*mField, volumeOptions, cachePath, slices);
}

bool ViewerApp::pollLoader()
{
    if (!mLoader || !mLoader->finished()) return false;
    std::unique_ptr<SceneLoader> loader = std::move(mLoader);
    mLoaded = loader->take();  // rethrows the loader's error
    const vdb::SurfaceVolume& volume = mLoaded->volume;
    const float interiorStep = float(volume.options.bandVoxels * volume.voxelSize());
    mRenderer->setVolume(mLoaded->slices, float(volume.voxelSize()), interiorStep);
    mVolumeText = mLoaded->slices.describe();
    std::printf("inversevis-view: volume %s (%s, %.1f s)\n", mLoaded->cachePath.c_str(),
                vdb::toString(mLoaded->cacheOutcome), mLoaded->seconds);
    std::printf("inversevis-view: %s\n", mVolumeText.c_str());
    std::fflush(stdout);
    mDirty = true;
    if (mOptions.optimise == "alpha") startOptimiser(false);
    if (mOptions.optimise == "view") startOptimiser(true);
    return true;
}

void ViewerApp::waitForScene()
{
    while (!pollLoader()) {
        glfwPollEvents();
        if (glfwWindowShouldClose(mWindow)) throw Cancelled("window closed while loading");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

GpuFrame ViewerApp::frame(int width, int height) const
{
    GpuFrame f;
    f.camera = mOrbit.camera();
    f.width = width;
    f.height = height;
    f.method = mMethod;
    f.shading = mShading;
    return f;
}

void ViewerApp::renderFrame(int width, int height)
{
    const GpuFrame f = frame(width, height);
    mLastFrameMs = timedMs([&] { mRenderer->render(f); });
}

void ViewerApp::takeNumberedScreenshot()
{
    const std::string path =
        "inversevis-view-" + core::sourceStem(mOptions.mesh.source) + "-" + std::to_string(++mScreenshots) + ".png";
    try {
        writeScreenshot(path, "");
        mStatus = "wrote " + path;
    } catch (const std::exception& e) {
        mStatus = e.what();
    }
}

void ViewerApp::writeScreenshot(const std::string& path, const std::string& regionPath)
{
    core::writePng(mRenderer->readColour(), path, false);
    if (!regionPath.empty()) {
        const std::vector<std::uint8_t> region = mRenderer->readRegion();
        const float grey[3] = {0.0f, core::linearFromSrgb(128.0f / 255.0f), 1.0f};
        core::Image image(mRenderer->width(), mRenderer->height());
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const float g = grey[std::min<int>(region[std::size_t(y) * image.width() + x], 2)];
                image.at(x, y) = glm::vec4(g, g, g, 1.0f);
            }
        core::writePng(image, regionPath, false);
    }
}

int ViewerApp::run()
{
    openWindow();
    startLoading();
    if (!mOptions.screenshot.empty()) return runHeadlessScreenshot();
    if (mOptions.benchmark) return runBenchmark();
    return runInteractive();
}

int ViewerApp::runHeadlessScreenshot()
{
    waitForScene();
    int fbWidth = 0, fbHeight = 0;
    for (int k = 0; k < mOptions.frames; ++k) {
        renderFrame(mOptions.width, mOptions.height);
        glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glViewport(0, 0, fbWidth, fbHeight);
        mRenderer->blitTo(0, 0, fbWidth, fbHeight);
        glfwSwapBuffers(mWindow);
        glfwPollEvents();
    }
    writeScreenshot(mOptions.screenshot, mOptions.regionPng);
    std::printf("inversevis-view: wrote %s (%dx%d, %s, %d frames, last frame %.1f ms, %s)\n",
                mOptions.screenshot.c_str(), mOptions.width, mOptions.height, render::toString(mMethod.method),
                mOptions.frames, mLastFrameMs, mGlRenderer.c_str());
    return 0;
}

int ViewerApp::runBenchmark()
{
    waitForScene();
    const double startPhi = mOrbit.phiDeg;
    renderFrame(mOptions.width, mOptions.height);  // warm-up: shader compilation, first upload
    const int frames = mOptions.benchmarkFrames;
    double slowest = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        mOrbit.fixed.reset();
        mOrbit.phiDeg = startPhi + 360.0 * i / frames;
        renderFrame(mOptions.width, mOptions.height);
        slowest = std::max(slowest, mLastFrameMs);
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        mRenderer->blitTo(0, 0, fbWidth, fbHeight);
        glfwSwapBuffers(mWindow);
        glfwPollEvents();
        if (glfwWindowShouldClose(mWindow)) break;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("inversevis-view: benchmark: %d frames orbiting 360 degrees at theta %.0f, %dx%d, %s, %s: %.2f fps "
                "(mean %.1f ms, slowest %.1f ms per frame)\n",
                frames, mOrbit.thetaDeg, mOptions.width, mOptions.height, render::toString(mMethod.method),
                mGlRenderer.c_str(), frames / seconds, 1000.0 * seconds / frames, slowest);
    return 0;
}

void ViewerApp::startOptimiser(bool view)
{
    if (!mLoaded || mJob.valid()) return;
    mCancelJob = false;
    mOptimiser.importanceRange = mShading.range;
    const ViewOptimiser optimiser = view ? viewpointOptimiser(mOptimiser) : parameterOptimiser(mOptimiser);
    mJobName = view ? "optimise view" : "optimise " + std::string(render::toString(mMethod.method));
    mStatus = mJobName + ": running on the CPU...";
    mJobStart = now();
    ViewState state{mOrbit.camera(), mMethod};
    const render::RenderScene* scene = mLoaded->scene.get();
    mJob = std::async(std::launch::async, [optimiser, scene, state, this] { return optimiser(*scene, state, mCancelJob); });
}

void ViewerApp::pollOptimiser(double time)
{
    if (!mJob.valid() || mJob.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    try {
        const OptimiserResult result = mJob.get();
        mStatus = result.summary;
        std::printf("inversevis-view: %s\n", mStatus.c_str());
        std::fflush(stdout);
        const float alpha = mMethod.curved.alpha;
        render::MethodParams target = result.state.method;
        target.method = mMethod.method;
        mMethod = target;
        mMethod.curved.alpha = alpha;  // animated below
        const OrbitCamera to = OrbitCamera::fromCamera(result.state.camera, false);
        mAnimation = CameraAnimation(mOrbit, alpha, to, result.state.method.curved.alpha, time, 1.0);
    } catch (const std::exception& e) {
        mStatus = mJobName + " failed: " + e.what();
    }
    mDirty = true;
}

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
            mDirty = true;
        }
        if (io.MouseWheel != 0.0f) {
            mAnimation.stop();
            mOrbit.zoom(io.MouseWheel);
            mDirty = true;
        }
    }
    if (!io.WantCaptureKeyboard) {
        if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) takeNumberedScreenshot();
        if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(mWindow, GLFW_TRUE);
    }
}

void ViewerApp::drawPanel()
{
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("inversevis", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    const float wrap = ImGui::GetFontSize() * 26.0f;
    ImGui::PushTextWrapPos(wrap);
    ImGui::Text("%s: %zu triangles, scalar '%s'", core::sourceStem(mOptions.mesh.source).c_str(),
                mField->mesh.triangles.size(), mField->hasScalar() ? mField->name.c_str() : "(none)");
    if (mLoader) {
        const int percent = mLoader->progress().percent();
        const std::string label = mLoader->progress().stage() + (percent >= 0 ? " " + std::to_string(percent) + "%" : "");
        ImGui::ProgressBar(percent >= 0 ? percent / 100.0f : 0.0f, ImVec2(wrap, 0), label.c_str());
        ImGui::TextUnformatted("loading the volume in the background; the direct part shows meanwhile");
    } else if (mLoaded) {
        ImGui::TextUnformatted(mVolumeText.c_str());
    }
    ImGui::Separator();

    bool changed = false;
    const std::vector<std::string> methods = render::methodNames();
    int method = int(mMethod.method);
    if (ImGui::BeginCombo("method", methods[std::size_t(method)].c_str())) {
        for (int i = 0; i < int(methods.size()); ++i)
            if (ImGui::Selectable(methods[std::size_t(i)].c_str(), i == method)) {
                mMethod.method = render::Method(i);
                changed = true;
            }
        ImGui::EndCombo();
    }
    const float reach = mLoaded ? mLoaded->slices.reach : 0.6f;
    switch (mMethod.method) {
    case render::Method::InverseVis:
        changed |= ImGui::SliderFloat("alpha", &mMethod.curved.alpha, 0.0f, 4.0f, "%.3f");
        changed |= curvedRaySliders(mMethod.curved, reach);
        break;
    case render::Method::InverseVisAdaptive:
        changed |= profileSliders(mMethod.profile);
        changed |= curvedRaySliders(mMethod.curved, reach);
        break;
    case render::Method::Mirror:
        for (int i = 0; i < 5; ++i) {
            const std::string label = "w" + std::to_string(i + 1);
            changed |= ImGui::SliderFloat(label.c_str(), &mMethod.mirror.w[std::size_t(i)], -1.0f, 1.0f, "%.3f");
        }
        changed |= ImGui::SliderFloat("behind", &mMethod.mirror.distanceBehind, 0.0f, 3.0f, "%.2f");
        break;
    case render::Method::Neugebauer:
        changed |= ImGui::SliderFloat("ring width", &mMethod.ring.ringWidth, 0.05f, 0.8f, "%.2f");
        changed |= ImGui::DragFloat3("centre", &mMethod.ring.centre.x, 0.01f, -1.0f, 1.0f, "%.2f");
        break;
    default: break;
    }
    ImGui::Separator();

    const std::vector<std::string> maps = core::colormapNames();
    if (ImGui::BeginCombo("colour map", maps[std::size_t(std::clamp(mColormapIndex, 0, int(maps.size()) - 1))].c_str())) {
        for (int i = 0; i < int(maps.size()); ++i)
            if (ImGui::Selectable(maps[std::size_t(i)].c_str(), i == mColormapIndex)) {
                mColormapIndex = i;
                mShading.colormap = maps[std::size_t(i)];
                mRenderer->setColormap(mShading.colormap);
                changed = true;
            }
        ImGui::EndCombo();
    }
    if (mField->hasScalar()) {
        const float speed = std::max(1e-6f, (mDataRange.hi - mDataRange.lo) / 300.0f);
        float lo = mShading.range.lo, hi = mShading.range.hi;
        if (ImGui::DragFloatRange2("range", &lo, &hi, speed, 0.0f, 0.0f, "%.4g", "%.4g")) {
            if (lo < hi) {
                mShading.range = {lo, hi};
                changed = true;
            }
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("data")) {
            mShading.range = mDataRange;
            changed = true;
        }
        tooltip("reset the range to the data's minimum and maximum");
    }
    changed |= ImGui::Checkbox("shadows", &mShading.shadows);
    changed |= ImGui::SliderFloat("render scale", &mRenderScale, 0.25f, 1.0f, "%.2f");
    tooltip("fraction of the window's pixels traced (software OpenGL starts at 0.5)");
    ImGui::Separator();

    const bool busy = mJob.valid() || !mLoaded;
    {
        const std::vector<std::string> energies = {"visibility", "scalar"};
        const bool scalar = mOptimiser.optimization.energy == "scalar";
        if (ImGui::BeginCombo("energy", mOptimiser.optimization.energy.c_str())) {
            for (const std::string& name : energies)
                if ((name != "scalar" || mField->hasScalar()) &&
                    ImGui::Selectable(name.c_str(), name == mOptimiser.optimization.energy))
                    mOptimiser.optimization.energy = name;
            ImGui::EndCombo();
        }
        tooltip(scalar ? "scalar: sum of the normalised scalar over the pixels that show the surface (METHOD.md)"
                       : "visibility: fraction of the surface voxels some ray lands in (METHOD.md, the paper's Table 1)");
        ImGui::SliderInt("opt. rays", &mOptimiser.resolution, 16, 400);
        tooltip("rays per image side while optimising (paper: 100 or 1000)");
        ImGui::SliderInt("anneal steps", &mOptimiser.optimization.steps, 1, 100);
        tooltip("proposals of the simulated annealing after the start view");
    }
    const bool hasParameters = mMethod.curvedRays() || mMethod.method == render::Method::Mirror;
    ImGui::BeginDisabled(busy || !hasParameters);
    if (ImGui::Button(optimiseLabel(mMethod.method))) startOptimiser(false);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: render::optimizeParameters, gradient ascent of the method's parameters "
            "(InverseVis alpha, the adaptive profile a0..a2, mirror w1..w5) with golden-section line searches on the "
            "true energy, at this view; alpha then eases to the result, the profile and w are set at once");
    ImGui::SameLine();
    ImGui::BeginDisabled(busy);
    if (ImGui::Button("optimise view")) startOptimiser(true);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: render::annealViewpoint, simulated annealing of the camera on the radius-2.5 "
            "sphere from this view, the parameters optimised at every proposal; the camera then eases to the best "
            "view. It cannot be interrupted.");
    if (mJob.valid()) {
        ImGui::SameLine();
        ImGui::Text("running %.0f s", now() - mJobStart);
    }
    ImGui::SameLine();
    if (ImGui::Button("screenshot (P)")) takeNumberedScreenshot();
    if (!mStatus.empty()) ImGui::TextUnformatted(mStatus.c_str());
    ImGui::Separator();
    ImGui::Text("frame %.1f ms (%.1f fps) at %dx%d", mLastFrameMs, mLastFrameMs > 0.0 ? 1000.0 / mLastFrameMs : 0.0,
                mRenderer->width(), mRenderer->height());
    ImGui::Text("camera theta %.1f phi %.1f distance %.2f", mOrbit.thetaDeg, mOrbit.phiDeg, mOrbit.distance);
    ImGui::TextDisabled("%s", mGlRenderer.c_str());
    ImGui::TextDisabled("drag: orbit; right/middle or shift-drag: pan; wheel: zoom; P: screenshot");
    ImGui::PopTextWrapPos();
    ImGui::End();
    if (changed) mDirty = true;
}

void ViewerApp::writeWindow(const std::string& path)
{
    int width = 0, height = 0;
    glfwGetFramebufferSize(mWindow, &width, &height);
    std::vector<std::uint8_t> bytes(std::size_t(width) * height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    checkGl("reading the window back");
    core::Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* p = bytes.data() + (std::size_t(height - 1 - y) * width + x) * 4;
            image.at(x, y) = glm::vec4(core::linearFromSrgb(p[0] / 255.0f), core::linearFromSrgb(p[1] / 255.0f),
                                       core::linearFromSrgb(p[2] / 255.0f), 1.0f);
        }
    core::writePng(image, path, false);
    std::printf("inversevis-view: wrote %s (window %dx%d, %s)\n", path.c_str(), width, height, mStatus.c_str());
}

int ViewerApp::runInteractive()
{
    int lastWidth = 0, lastHeight = 0, settledFrames = 0;
    while (!glfwWindowShouldClose(mWindow)) {
        const bool busy = mDirty || mLoader || mJob.valid() || mAnimation.started();
        if (busy) glfwPollEvents();
        else glfwWaitEventsTimeout(0.25);
        pollLoader();
        const double time = now();
        pollOptimiser(time);
        if (mAnimation.started()) {
            mAnimation.at(time, mOrbit, mMethod.curved.alpha);
            if (!mAnimation.active(time)) mAnimation.stop();
            mDirty = true;
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        drawPanel();
        handleInput();
        ImGui::Render();

        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
        if (fbWidth > 0 && fbHeight > 0) {
            const int width = std::max(16, int(std::lround(fbWidth * mRenderScale)));
            const int height = std::max(16, int(std::lround(fbHeight * mRenderScale)));
            if (mDirty || width != lastWidth || height != lastHeight) {
                renderFrame(width, height);
                lastWidth = width;
                lastHeight = height;
                mDirty = false;
            }
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glViewport(0, 0, fbWidth, fbHeight);
            glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            mRenderer->blitTo(0, 0, fbWidth, fbHeight);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
        if (!mOptions.uiScreenshot.empty() && !mLoader && !mJob.valid() && !mAnimation.started() &&
            ++settledFrames >= mOptions.frames + 1) {
            writeWindow(mOptions.uiScreenshot);
            break;
        }
        glfwSwapBuffers(mWindow);
    }
    return 0;
}

}  // namespace ivis::app
