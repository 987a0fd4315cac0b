#include "viewer_app.h"

#include "gl_window.h"
#include "viewer_clock.h"
#include "viewer_panel.h"

#include "../mesh_options.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/method_json.h>

#include <epoxy/gl.h>
// GLFW after epoxy: epoxy provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

namespace ivis::app {
namespace {

/// The picture moves right of the open panel (at the window's left edge) when that leaves it at
/// least this share of the window's width; a narrower window keeps the panel over the picture.
constexpr double kDockedPictureShare = 0.5;

}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, core::SurfaceField field,
                     std::unique_ptr<core::SurfaceSeries> series, SeriesSurvey survey)
    : mOptions(options),
      mField(std::make_unique<core::SurfaceField>(std::move(field))),
      mSeries(std::move(series)),
      mSurvey(std::move(survey)),
      mCacheFolder(vdb::optionalCacheFolder(options.cacheDir))  // once: a series' every geometry would warn
{
    mPlayRate = float(mOptions.playRate);
    mOptions.view.resolution = std::to_string(options.width) + "x" + std::to_string(options.height);
    const render::RenderOptions render = mOptions.view.renderOptions(*mField);
    mMethod = render.method;
    mShading = render.shading;
    mLegendSide = render.legendSide;
    mShowLegend = render.legend;
    mOutline = render.outline;
    const core::ColorScaleRequest scaleRequest = mOptions.view.colorScaleRequest();
    mDataScale = scaleRequest.resolve(mSeries ? mSurvey.sample : mField->values,
                                      mSeries ? mSeries->source() : mField->sourcePath);
    if (mSeries) mShading.scale = mDataScale;  // one scale for every step
    mOptimiser.optimization = mOptions.optimization;
    mOptimiser.resolution = mOptions.optResolution;
    mOptimiser.views = mOptions.views;
    mOptions.optimization.energyOptions(mOptions.optResolution, mShading.scale.range);  // validates --energy
    mOrbit = OrbitCamera::fromCamera(mOptions.view.camera(), !mOptions.view.cameraFile.empty());
    mOrbit.framed = mOptions.view.framed();
    mProbePending = !mOptions.probe.empty();
    const std::vector<std::string> names = core::colormapNames();
    mColormapIndex = int(std::find(names.begin(), names.end(), mShading.colormap) - names.begin());
    mOpenedUnits = render.units;
    if (!mSeries || mSeries->steps().front().array.empty()) {  // a pattern's steps are its arrays
        mArrayChoices = core::arrayChoices(*mField);
        // A file's array as it is, not hot spots, a scalar file or an array averaged onto the vertices.
        const core::SurfaceLoadOptions& load = mOptions.mesh.load;
        const bool fileArray = load.hotSpots == 0 && load.read.scalarFile.empty() && !load.read.cellToPoint;
        for (std::size_t i = 0; fileArray && i < mArrayChoices.size() && mArrayChoice < 0; ++i)
            if (mArrayChoices[i].name == mField->name && mArrayChoices[i].association == mField->valuesOn)
                mArrayChoice = int(i);
        if (mArrayChoice < 0 && mField->hasScalar())
            mOpenedScalar = OpenedScalar{mSeries ? std::vector<float>() : mField->values, mField->valuesOn, mField->name};
        mOpenedChoice = mArrayChoice;
        mOpenedScale = mShading.scale;
        mOpenedDataScale = mDataScale;
    }
}

ViewerApp::~ViewerApp()
{
    mCancelJob = true;
    if (mJob.valid() && mJob.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        std::printf("inversevis-view: stopping the running optimisation at its next line search or proposal\n");
        std::fflush(stdout);
        mJob.wait();
    }
    if (mColouring.valid()) mColouring.wait();  // stops before its next step
    mCpuTracer.cancel();
    mLoader.reset();  // cancels and joins
    closeWindow();
}

void ViewerApp::openWindow()
{
    initGlfw();
    mGlfwReady = true;
    const std::string title = "inversevis-view: " + core::sourceStem(mOptions.mesh.source);
    mWindow = createGlWindow(title, mOptions.width, mOptions.height, mOptions.screenshot.empty());
    glfwSwapInterval(mOptions.headless() ? 0 : 1);
    mGlRenderer = glRendererName();
    mRenderer = std::make_unique<GpuRenderer>();
    mColorBar = std::make_unique<ColorBarOverlay>();
    mNormals = render::vertexNormals(mField->mesh);
    mVertices = std::make_unique<core::ClusteredVertices>(mField->mesh.positions);
    mRenderer->setMesh(*mField, mNormals);
    mRenderer->setColormap(mShading.colormap);
    // Software rasterisers run the shaders on the CPU, slower than the CPU renderer: there the CPU
    // renderer traces the picture (--tracer auto); shaders on software GL start at half
    // resolution, and at half of that while the camera moves.
    const bool softwareGl = isSoftwareGl(mGlRenderer);
    mCpuTracing = mOptions.tracer == "cpu" || (mOptions.tracer == "auto" && softwareGl);
    if (softwareGl && !mCpuTracing) {
        mRenderScale = 0.5f;
        mInteraction.reduction = 0.5f;
    }
    if (!mOptions.headless()) {
        startImGui(mWindow);
        mImGuiReady = true;
    }
}

void ViewerApp::closeWindow()
{
    if (mImGuiReady) stopImGui();
    mImGuiReady = false;
    mColorBar.reset();  // GL objects go before their context
    mRenderer.reset();
    if (mWindow) glfwDestroyWindow(mWindow);
    mWindow = nullptr;
    if (mGlfwReady) glfwTerminate();
    mGlfwReady = false;
}

void ViewerApp::startLoading()
{
    const vdb::VolumeOptions volumeOptions = mOptions.mesh.volumeOptions();
    const std::string cachePath =
        vdb::defaultVolumePath(mCacheFolder, mOptions.mesh.source, mField->mesh, volumeOptions);
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
    stopCpuPicture();  // it reads the scene replaced
    mLoaded = loader->take();  // rethrows the loader's error
    const vdb::SurfaceVolume& volume = mLoaded->volume;
    const float interiorStep = float(volume.options.bandVoxels * volume.voxelSize());
    mRenderer->setVolume(mLoaded->slices, float(volume.voxelSize()), interiorStep);
    mVolumeText = mLoaded->slices.describe();
    std::printf("inversevis-view: volume %s (%s, %.1f s)\n",
                mLoaded->cachePath.empty() ? "not kept" : mLoaded->cachePath.c_str(),
                vdb::toString(mLoaded->cacheOutcome), mLoaded->seconds);
    std::printf("inversevis-view: %s\n", mVolumeText.c_str());
    std::fflush(stdout);
    mDirty = true;
    if (mOptions.optimise == "parameters") startOptimiser(Job::Parameters);
    if (mOptions.optimise == "view") startOptimiser(Job::View);
    // An interactive window draws the rule render would choose (--screenshot and --benchmark the given one).
    if (mOptions.optimise.empty() && mOptions.screenshot.empty() && !mOptions.benchmark && choosesReadableRule())
        startOptimiser(Job::ReadableRule);
    return true;
}

void ViewerApp::waitForScene()
{
    while (!pollLoader()) {
        glfwPollEvents();
        if (glfwWindowShouldClose(mWindow)) throw Cancelled("window closed while loading");
        if (core::interruptRequested()) throw Cancelled("interrupted");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
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

int ViewerApp::runInteractive()
{
    setPlaying(mOptions.play);
    int lastWidth = 0, lastHeight = 0, settledFrames = 0;
    while (!glfwWindowShouldClose(mWindow)) {
        const bool busy = mDirty || mLoader || jobRunning() || mAnimation.started() ||
                          (mRestWanted && !cameraMovesForCpu());
        if (busy) glfwPollEvents();
        else if (mCpuTracer.resting()) glfwWaitEvents();  // until an input or the CPU's picture is done
        else {
            // Woken when a wheel click's rest time ends too, so the full picture follows it at once.
            double idle = mPlaying ? std::clamp(mNextStepTime - now(), 0.001, 0.25) : 0.25;
            if (const double rest = mInteraction.secondsUntilRest(now()); rest > 0.0) idle = std::min(idle, rest);
            glfwWaitEventsTimeout(idle);
        }
        pollLoader();
        const double time = now();
        pollOptimiser(time);
        pollSeriesColouring();
        advancePlayback(time);
        if (mAnimation.started()) {
            std::vector<double> parameters;
            mAnimation.at(time, mOrbit, parameters);
            if (!parameters.empty() && mMethod->name() == mAnimatedMethod)  // unless switched meanwhile
                mMethod = render::withOptimisedParameters(*mMethod, parameters);
            if (!mAnimation.active(time)) {
                mAnimation.stop();
                std::printf("inversevis-view: drawing %s\n", render::methodToJson(*mMethod).dump().c_str());
                std::fflush(stdout);
            }
            mDirty = true;
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        drawPanel();
        handleInput();
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
        PictureViewport picture{0, 0, fbWidth, fbHeight};
        if (fbWidth > 0 && fbHeight > 0) {
            int strip = int(std::ceil(mPanelDock));
            if (fbWidth - strip < kDockedPictureShare * fbWidth) strip = 0;
            picture = mColorBar->place(legendContent(), mLegendSide, mShowLegend && mField->hasScalar(), strip, fbWidth,
                                       fbHeight);
            mColorBar->draw(*ImGui::GetBackgroundDrawList(), ImGui::GetIO().DisplayFramebufferScale);
            if (mLoaded) {
                const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
                mProbe.drawMarker(*ImGui::GetBackgroundDrawList(), *mLoaded->scene, mMethod, mOrbit.camera(), picture,
                                  fbHeight, {scale.x, scale.y});
            }
        }
        ImGui::Render();

        if (fbWidth > 0 && fbHeight > 0) {
            mPicture = picture;
            const float scale = tracesOnCpu() ? mRenderScale : mInteraction.scale(mRenderScale, now());
            const int width = std::max(16, int(std::lround(picture.width * scale)));
            const int height = std::max(16, int(std::lround(picture.height * scale)));
            if (tracesOnCpu()) {
                traceOnCpu(width, height, cameraMovesForCpu());
            } else if (mDirty || width != lastWidth || height != lastHeight) {
                renderFrame(width, height);
                lastWidth = width;
                lastHeight = height;
                mDirty = false;
            }
            // --probe, once the camera and the method have settled (a readable rule chosen at start).
            if (mProbePending && mLoaded && !jobRunning() && !mAnimation.started()) {
                mProbePending = false;
                const glm::ivec2 pixel = parseProbePixel(mOptions.probe, mOptions.width, mOptions.height);
                if (pixel.x < picture.width && pixel.y < picture.height) probeAt(pixel);
                else mStatus = "--probe " + mOptions.probe + ": outside the picture beside the panel and the colour bar";
            }
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glViewport(0, 0, fbWidth, fbHeight);
            glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            mRenderer->blitTo(picture.x, picture.y, picture.width, picture.height);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
        if (!mOptions.uiScreenshot.empty() && !mLoader && !jobRunning() && !mAnimation.started() && !mPlaying &&
            !mRestWanted && !mCpuTracer.resting() &&
            ++settledFrames >= mOptions.frames + 1) {
            writeWindow(mOptions.uiScreenshot);
            break;
        }
        glfwSwapBuffers(mWindow);
    }
    return 0;
}

}  // namespace ivis::app
