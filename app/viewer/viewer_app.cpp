#include "viewer_app.h"

#include "gl_window.h"
#include "viewer_panel.h"

#include "../frame_video.h"
#include "../mesh_options.h"

#include <ivis/vdb/cache_folder.h>
#include <ivis/core/colormap.h>
#include <ivis/core/errors.h>
#include <ivis/core/image_io.h>
#include <ivis/core/interrupt_signal.h>
#include <ivis/core/log.h>
#include <ivis/core/surface_source.h>
#include <ivis/render/framing.h>
#include <ivis/render/method_json.h>
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
#include <vector>

namespace ivis::app {
namespace {

double now() { return glfwGetTime(); }

/// The panel's text width and its widgets' width, in font heights: narrow enough that the picture
/// keeps most of the window.
constexpr float kPanelWidthEm = 20.0f;
constexpr float kPanelItemWidthEm = 11.0f;
/// The panel's distance from the window's top left corner where it opens.
constexpr float kPanelMargin = 8.0f;
/// The picture moves right of the open panel (at the window's left edge) when that leaves it at
/// least this share of the window's width; a narrower window keeps the panel over the picture.
constexpr double kDockedPictureShare = 0.5;

/// Milliseconds taken by @a work, waiting for the GPU to finish.
template <typename Work>
double timedMs(Work&& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// Seconds since @a start.
double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

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
    mDataScale = scaleRequest.resolve(mSeries ? mSurvey.sample : mField->values);
    if (mSeries) mShading.scale = mDataScale;  // one scale for every step
    mOptimiser.optimization = mOptions.optimization;
    mOptimiser.resolution = mOptions.optResolution;
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

void ViewerApp::showStep(std::size_t step)
{
    IVIS_CHECK(mSeries && step < mSeries->steps().size() && !jobRunning());
    core::SurfaceField field = mSeries->load(step);
    mCpuTracer.cancel();  // it reads the field and the scene
    const bool sameGeometry = mSurvey.meshHashes[step] == mSurvey.meshHashes[mStep];
    mStep = step;
    const core::SeriesStep& shown = mSeries->steps()[step];
    if (sameGeometry) {
        // The mesh stays (the loaded scene and the GPU volume refer to it); only what it shows changes.
        core::showStepData(*mField, std::move(field));
        mProbe.readScalar(*mField);
    } else {
        mLoader.reset();  // cancels and joins: it reads the field being replaced
        mLoaded.reset();
        mRenderer->dropVolume();
        mField = std::make_unique<core::SurfaceField>(std::move(field));
        mNormals = render::vertexNormals(mField->mesh);
        mProbe.clear();  // its triangle is of the other mesh
    }
    mRenderer->setMesh(*mField, mNormals);
    if (!sameGeometry) startLoading();
    std::printf("inversevis-view: step %zu/%zu (%s): %s\n", step + 1, mSeries->steps().size(), shown.label.c_str(),
                sameGeometry ? "volume kept" : "other geometry, loading its volume");
    std::fflush(stdout);
    mDirty = true;
}

void ViewerApp::switchStep(std::size_t step)
{
    if (step == mStep) return;
    try {
        showStep(step);
    } catch (const std::exception& e) {  // a step's file changed on disk since it was checked
        mStatus = e.what();
    }
}

void ViewerApp::setPlaying(bool playing)
{
    mPlaying = playing && mSeries;
    if (!mPlaying) return;
    if (mStep + 1 == mSeries->steps().size() && !jobRunning()) switchStep(0);
    mNextStepTime = now() + 1.0 / mPlayRate;
}

void ViewerApp::advancePlayback(double time)
{
    if (!mPlaying) return;
    const double interval = 1.0 / mPlayRate;
    if (jobRunning() || mLoader) {  // the step is shown a whole interval once its volume and the job are done
        mNextStepTime = time + interval;
        return;
    }
    if (time < mNextStepTime) return;
    const std::size_t count = mSeries->steps().size();
    if (mStep + 1 == count && !mLoop) {
        mPlaying = false;
        return;
    }
    const std::size_t next = (mStep + 1) % count;
    switchStep(next);
    if (mStep != next) mPlaying = false;  // the step failed: its error is on the status line
    mNextStepTime = std::max(mNextStepTime + interval, time);  // the rate kept over the frames' rounding
}

bool ViewerApp::pollLoader()
{
    if (!mLoader || !mLoader->finished()) return false;
    std::unique_ptr<SceneLoader> loader = std::move(mLoader);
    mCpuTracer.cancel();  // it reads the scene replaced
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

core::ColorBarContent ViewerApp::legendContent() const
{
    const std::string title = mSeries ? seriesStepTitle(*mSeries, mSeries->steps()[mStep], mField->name) : mField->name;
    return {mShading.colormap, mShading.scale, title, shownUnits()};
}

GpuFrame ViewerApp::frame(int width, int height) const
{
    GpuFrame f;
    f.camera = mOrbit.camera();
    f.width = width;
    f.height = height;
    f.method = mMethod;
    f.shading = mShading;
    f.outline = mOutline;
    return f;
}

void ViewerApp::frameOrbit(int width, int height)
{
    const core::Camera camera = mOrbit.camera();
    const double aspect = double(width) / double(height);
    try {
        const core::Camera framed =
            mLoaded ? render::frameView(*mLoaded->scene, camera, *mMethod, aspect)
                    : render::fitCamera(camera, render::offsetMeshExtent(mField->mesh, camera, 0.0), aspect);
        mOrbit.fovYDeg = framed.fovYDeg;
        mOrbit.orthoHalfHeight = framed.orthoHalfHeight;
        mOrbit.windowCentre = framed.windowCentre;
    } catch (const ValueError& e) {
        mOrbit.framed = false;
        mStatus = std::string("framing off: ") + e.what();
    }
}

void ViewerApp::renderFrame(int width, int height)
{
    if (mOrbit.framed) frameOrbit(width, height);
    if (tracesOnCpu()) {
        mLastFrameMs = timedMs([&] {
            mRenderer->show(render::renderImage(*mLoaded->scene, mOrbit.camera(), cpuOptions(width, height)));
        });
        return;
    }
    const GpuFrame f = frame(width, height);
    mLastFrameMs = timedMs([&] { mRenderer->render(f); });
}

render::RenderOptions ViewerApp::cpuOptions(int width, int height) const
{
    render::RenderOptions options;
    options.width = width;
    options.height = height;
    options.method = mMethod;
    options.shading = mShading;
    options.outline = mOutline;
    options.legend = false;  // the window draws its own colour bar
    return options;
}

bool ViewerApp::traceOnCpu(int width, int height, bool moving)
{
    if (mDirty || width != mCpuSize.x || height != mCpuSize.y) {
        if (mOrbit.framed) frameOrbit(width, height);
        mLastFrameMs = timedMs([&] {
            mRenderer->show(mCpuTracer.renderMoving(*mLoaded->scene, mOrbit.camera(), cpuOptions(width, height)));
        });
        mCpuSize = {width, height};
        mDirty = false;
        mRestWanted = true;
    }
    if (mRestWanted && !moving) {
        mCpuTracer.startResting(*mLoaded->scene, mOrbit.camera(), cpuOptions(width, height));
        mRestStart = now();
        mRestWanted = false;
    }
    if (std::optional<render::RenderResult> picture = mCpuTracer.takeResting()) {
        mRenderer->show(*picture);
        mLastFrameMs = 1000.0 * (now() - mRestStart);
        return true;
    }
    return false;
}

void ViewerApp::takeNumberedScreenshot()
{
    if (tracesOnCpu() && (mRestWanted || mCpuTracer.resting())) {  // the full picture, not a moving frame
        mCpuTracer.cancel();
        renderFrame(mCpuSize.x, mCpuSize.y);
        mRestWanted = false;
    }
    const std::string path =
        "inversevis-view-" + core::sourceStem(mOptions.mesh.source) + "-" + std::to_string(++mScreenshots) + ".png";
    try {
        core::AtomicFileSet files;
        writeScreenshot(files, path, "");
        files.commit();
        mStatus = "wrote " + path;
    } catch (const std::exception& e) {
        mStatus = e.what();
    }
}

void ViewerApp::saveView()
{
    const std::string path =
        "inversevis-view-" + core::sourceStem(mOptions.mesh.source) + "-" + std::to_string(++mSavedViews) + ".view.json";
    render::RenderOptions look = mOptions.view.renderOptions();
    look.width = mPicture.width > 0 ? mPicture.width : mOptions.width;
    look.height = mPicture.height > 0 ? mPicture.height : mOptions.height;
    look.method = mMethod;
    look.shading = mShading;
    look.legend = mShowLegend;
    look.legendSide = mLegendSide;
    look.outline = mOutline;
    look.units = shownUnits();
    try {
        writeViewFile(viewOfPicture(mOrbit.camera(), look, shownScalarLoad(), mField->normalization), path);
        mStatus = "wrote " + path;
    } catch (const std::exception& e) {
        mStatus = e.what();
    }
}

void ViewerApp::writeScreenshot(core::AtomicFileSet& files, const std::string& path, const std::string& regionPath)
{
    const core::Image picture = mRenderer->readColour();
    const bool legend = mShowLegend && mField->hasScalar();
    files.write(path, [&](const std::string& temporary) {
        core::writePng(legend ? core::withColorBar(picture, legendContent(), mLegendSide,
                                                   glm::vec4(mShading.background, 1.0f))
                              : picture,
                       temporary, false);
    });
    if (!regionPath.empty()) {
        files.write(regionPath, [&](const std::string& temporary) {
            core::writePng(regionImage(mRenderer->readRegion(), mRenderer->width(), mRenderer->height()), temporary,
                           false);
        });
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
    // A series: every step in turn, as the time slider shows it, one numbered screenshot each,
    // renamed into place together once all are written (Ctrl-C leaves none, as render's frames).
    const std::size_t steps = mSeries ? mSeries->steps().size() : 1;
    core::AtomicFileSet files;
    std::vector<std::string> written;
    for (std::size_t step = 0; step < steps; ++step) {
        if (step > 0) showStep(step);
        if (mLoader) waitForScene();
        int fbWidth = 0, fbHeight = 0;
        for (int k = 0; k < mOptions.frames; ++k) {
            renderFrame(mOptions.width, mOptions.height);
            glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glViewport(0, 0, fbWidth, fbHeight);
            mRenderer->blitTo(0, 0, fbWidth, fbHeight);
            glfwSwapBuffers(mWindow);
            glfwPollEvents();
            if (core::interruptRequested()) throw Cancelled("interrupted");
        }
        const auto numbered = [&](const std::string& path) {
            return mSeries && !path.empty() ? framePath(path, step, steps) : path;
        };
        const std::string path = numbered(mOptions.screenshot);
        writeScreenshot(files, path, numbered(mOptions.regionPng));
        char frame[64];
        std::snprintf(frame, sizeof frame, "%.1f ms", mLastFrameMs);
        written.push_back("inversevis-view: wrote " + path + " (" + std::to_string(mOptions.width) + "x" +
                          std::to_string(mOptions.height) + ", " + mMethod->name() + ", " +
                          std::to_string(mOptions.frames) + " frames, last frame " + frame + ", " + mGlRenderer +
                          ")\n");
        if (mProbePending)
            written.push_back("inversevis-view: " +
                              mProbe.probe(*mLoaded->scene, mMethod, mOrbit.camera(), mOptions.width, mOptions.height,
                                           parseProbePixel(mOptions.probe, mOptions.width, mOptions.height)) +
                              "\n");
    }
    files.commit();
    for (const std::string& line : written) std::fputs(line.c_str(), stdout);
    return 0;
}

int ViewerApp::runBenchmark()
{
    waitForScene();
    const double startPhi = mOrbit.phiDeg;
    const int width = mOptions.width, height = mOptions.height;
    renderFrame(width, height);  // warm-up: shader compilation, first upload, the volume's pages
    const auto show = [&] {
        int fbWidth = 0, fbHeight = 0;
        glfwGetFramebufferSize(mWindow, &fbWidth, &fbHeight);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        mRenderer->blitTo(0, 0, fbWidth, fbHeight);
        glfwSwapBuffers(mWindow);
        glfwPollEvents();
        if (glfwWindowShouldClose(mWindow)) throw Cancelled("window closed");
        if (core::interruptRequested()) throw Cancelled("interrupted");
    };
    // While the camera moves: each frame as the window draws it then (the CPU: at the size its frame
    // time allows; shaders: the render scale times the interaction scale).
    const int frames = mOptions.benchmarkFrames;
    const float movingScale = mRenderScale * mInteraction.reduction;
    double slowest = 0.0;  // wall time of a whole frame
    glm::dvec2 traced(0.0);  // the traced sizes, summed
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        const auto frameStart = std::chrono::steady_clock::now();
        mOrbit.fixed.reset();
        mOrbit.phiDeg = startPhi + 360.0 * i / frames;
        mDirty = true;
        if (tracesOnCpu()) traceOnCpu(width, height, true);
        else renderFrame(std::max(16, int(std::lround(width * movingScale))), std::max(16, int(std::lround(height * movingScale))));
        traced += glm::dvec2(mRenderer->width(), mRenderer->height());
        show();
        slowest = std::max(slowest, secondsSince(frameStart));
    }
    const double seconds = secondsSince(start);
    // At rest: until the full-size picture is shown.
    const auto restStart = std::chrono::steady_clock::now();
    if (tracesOnCpu()) {
        while (!traceOnCpu(width, height, false)) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    } else {
        renderFrame(width, height);
    }
    show();
    const double rest = secondsSince(restStart);
    std::printf("inversevis-view: benchmark: %d frames orbiting 360 degrees at theta %.0f, %dx%d, %s, %s, traced by "
                "%s: moving %.2f fps (mean %.1f ms, slowest %.1f ms per frame, mean traced size %.0fx%.0f); at rest "
                "the full %dx%d picture in %.2f s\n",
                frames, mOrbit.thetaDeg, width, height, mMethod->name().c_str(), mGlRenderer.c_str(),
                tracesOnCpu() ? "the CPU" : "the shaders", frames / seconds, 1000.0 * seconds / frames, 1000.0 * slowest,
                traced.x / frames, traced.y / frames, width, height, rest);
    return 0;
}

bool ViewerApp::choosesReadableRule() const
{
    const std::string& key = mMethod->info().readabilityParameter;
    return mOptions.optimization.minCoherence > 0.0 && !key.empty() && !mOptions.view.givesParameter(key);
}

void ViewerApp::startOptimiser(Job job)
{
    if (!mLoaded || jobRunning()) return;
    mCancelJob = false;
    mOptimiser.importanceRange = mShading.scale.range;
    mOptimiser.framed = mOrbit.framed;
    const ViewOptimiser optimiser = job == Job::View         ? viewpointOptimiser(mOptimiser)
                                    : job == Job::Parameters ? parameterOptimiser(mOptimiser)
                                                             : readableRuleOptimiser(mOptimiser);
    mJobName = job == Job::View ? "optimise view" : job == Job::Parameters ? "optimise " + mMethod->name() : "readable rule";
    mStatus = mJobName + ": running on the CPU...";
    mJobStart = now();
    mJobMethod = mMethod;
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
        // Unless the method was changed meanwhile, it takes the result's other parameters (the
        // readable rule) now and its optimised ones ease to the result's.
        const bool sameMethod = mMethod == mJobMethod;
        if (sameMethod) mMethod = render::withOptimisedParameters(*result.state.method, render::optimisedParameters(*mMethod));
        mAnimatedMethod = mMethod->name();
        const OrbitCamera to = OrbitCamera::fromCamera(result.state.camera, false);
        mAnimation = CameraAnimation(mOrbit, sameMethod ? render::optimisedParameters(*mMethod) : std::vector<double>{},
                                     to, sameMethod ? render::optimisedParameters(*result.state.method) : std::vector<double>{},
                                     time, 1.0);
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

void ViewerApp::drawPanel()
{
    ImGui::SetNextWindowPos(ImVec2(kPanelMargin, kPanelMargin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("inversevis", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * kPanelWidthEm);
    ImGui::PushItemWidth(ImGui::GetFontSize() * kPanelItemWidthEm);
    drawSourceLines();
    bool changed = false;
    if (ImGui::CollapsingHeader("method##section", ImGuiTreeNodeFlags_DefaultOpen))
        changed |= methodWidgets(mMethod, mLoaded ? mLoaded->slices.reach : 0.6f);
    if (ImGui::CollapsingHeader("colour##section", ImGuiTreeNodeFlags_DefaultOpen)) {
        changed |= drawColourByCombo();
        const std::string colormap = mShading.colormap;
        changed |= lookWidgets(mShading, mColormapIndex, mDataScale, mField->hasScalar());
        changed |= ImGui::Checkbox("outline", &mOutline);
        tooltip("dark outline around the directly visible object, so direct and indirect parts are told apart");
        if (mField->hasScalar()) {
            ImGui::SameLine();
            ImGui::Checkbox("colour bar", &mShowLegend);
        }
        if (mShading.colormap != colormap) mRenderer->setColormap(mShading.colormap);
    }
    if (ImGui::CollapsingHeader("optimise##section", ImGuiTreeNodeFlags_DefaultOpen)) drawOptimiserSection();
    if (ImGui::CollapsingHeader("probe##section", ImGuiTreeNodeFlags_DefaultOpen))
        if (const std::optional<glm::dvec2> view = mProbe.widgets(*mField)) turnTo(*view);
    if (ImGui::CollapsingHeader("picture##section")) changed |= drawPictureSection();
    ImGui::Separator();
    if (ImGui::Button("screenshot (P)")) takeNumberedScreenshot();
    ImGui::SameLine();
    if (ImGui::Button("save view")) saveView();
    tooltip("write the view file of this picture (camera, method and parameters, scalar, colour): "
            "`inversevis render --view FILE` and `inversevis-view --view FILE` show it again");
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    tooltip(mSeries ? "drag: orbit; right/middle or shift-drag: pan; wheel: zoom; F: frame; P: screenshot; "
                      "left/right: time step; space: play / pause"
                    : "drag: orbit; right/middle or shift-drag: pan; wheel: zoom; F: frame; P: screenshot");
    if (!mStatus.empty()) ImGui::TextUnformatted(mStatus.c_str());
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    mPanelSize = glm::ivec2(int(ImGui::GetWindowWidth() * scale.x), int(ImGui::GetWindowHeight() * scale.y));
    const ImVec2 corner = ImGui::GetWindowPos();
    const bool atTopLeft = corner.x <= 2.0f * kPanelMargin && corner.y <= 2.0f * kPanelMargin;
    mPanelDock = atTopLeft && !ImGui::IsWindowCollapsed() ? (corner.x + ImGui::GetWindowWidth()) * scale.x : 0.0f;
    ImGui::End();
    if (changed) mDirty = true;
}

void ViewerApp::drawSourceLines()
{
    ImGui::Text("%s: %zu triangles, scalar '%s'", core::sourceStem(mOptions.mesh.source).c_str(),
                mField->mesh.triangles.size(), mField->hasScalar() ? mField->name.c_str() : "(none)");
    if (mSeries) {
        const std::size_t count = mSeries->steps().size();
        int step = int(mStep);
        const core::SeriesStep& shown = mSeries->steps()[mStep];
        std::string format;  // the slider's text is a printf format: a '%' of the label doubled
        for (const char c : shown.label) format += c == '%' ? std::string("%%") : std::string(1, c);
        ImGui::BeginDisabled(jobRunning());
        if (ImGui::SliderInt("time step", &step, 0, int(count) - 1, format.c_str(), ImGuiSliderFlags_AlwaysClamp)) {
            mPlaying = false;  // the hand that holds the slider chooses the step
            switchStep(std::size_t(step));
        }
        ImGui::EndDisabled();
        tooltip("The steps of the time series (time of each from the .pvd; its index for files, a --scalar "
                "pattern or a .pvd without times); one colour range over all steps; the volume stays while the geometry does. Disabled "
                "while an optimiser or the survey of 'colour by' runs.");
        ImGui::BeginDisabled(jobRunning() && !mPlaying);  // a pause is always possible
        if (ImGui::Button(mPlaying ? "pause" : "play")) setPlaying(!mPlaying);
        ImGui::EndDisabled();
        tooltip("play (space): the steps one after the other at steps/s, each shown a whole interval once its volume "
                "is loaded, from the first when the slider is at the last; it waits while an optimiser or 'colour by' "
                "runs, and the slider pauses it");
        ImGui::SameLine();
        ImGui::Checkbox("loop", &mLoop);
        tooltip("play on from the last step to the first");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5.0f);
        ImGui::DragFloat("steps/s", &mPlayRate, 0.1f, 0.1f, 60.0f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
        tooltip("steps per second while playing (--play-rate)");
        if (mSeries->timed()) ImGui::Text("step %zu of %zu, time %g", mStep + 1, count, shown.time);
        else ImGui::Text("step %zu of %zu, %s", mStep + 1, count, shown.label.c_str());
    }
    if (mLoader) {
        const int percent = mLoader->progress().percent();
        const std::string label = mLoader->progress().stage() + (percent >= 0 ? " " + std::to_string(percent) + "%" : "");
        ImGui::ProgressBar(percent >= 0 ? percent / 100.0f : 0.0f, ImVec2(ImGui::GetFontSize() * kPanelWidthEm, 0),
                           label.c_str());
        ImGui::TextUnformatted("loading the volume in the background; the direct part shows meanwhile");
    }
}

void ViewerApp::drawOptimiserSection()
{
    const bool busy = jobRunning() || !mLoaded;
    optimiserWidgets(mOptimiser, mField->hasScalar());
    const bool hasParameters = !render::optimisedParameters(*mMethod).empty();
    ImGui::BeginDisabled(busy || !hasParameters);
    if (ImGui::Button(optimiseLabel(*mMethod).c_str())) startOptimiser(Job::Parameters);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::optimizeParameters, gradient ascent of the method's optimised "
            "parameters with golden-section line searches on the true energy, at this view; they then ease to the "
            "result");
    ImGui::SameLine();
    ImGui::BeginDisabled(busy);
    if (ImGui::Button("optimise view")) startOptimiser(Job::View);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::annealViewpoint, simulated annealing of the camera on the radius-2.5 "
            "sphere from this view, the parameters optimised at every proposal; the camera then eases to the best "
            "view. Closing the window stops it.");
    ImGui::SameLine();
    ImGui::BeginDisabled(busy || mMethod->info().readabilityParameter.empty());
    if (ImGui::Button("readable rule")) startOptimiser(Job::ReadableRule);
    ImGui::EndDisabled();
    tooltip("CPU, in the background: optimize::loosestReadable, the loosest rule for drawing rays (inversevis-wrap: "
            "stable_shift, from an eighth of its default to 8 times it) whose 1000 x 1000 picture from this view keeps the "
            "mapping coherence --min-coherence (0.99), as render chooses it; done at start when the rule is not given");
    if (mJob.valid()) ImGui::Text("running %.0f s", now() - mJobStart);
}

bool ViewerApp::drawColourByCombo()
{
    if (mArrayChoices.empty()) return false;
    auto label = [&](int i) {
        if (i < 0) return mOpenedScalar ? mOpenedScalar->name : std::string("(none)");
        const core::ArrayChoice& c = mArrayChoices[std::size_t(i)];
        return c.association == core::Association::Cell ? c.name + " (cell)" : c.name;
    };
    const int shown = mArrayChoice;
    // A series waits for its volume: the loader's end may start the readable rule, which waits for no survey.
    ImGui::BeginDisabled(jobRunning() || (mSeries && mLoader));
    if (ImGui::BeginCombo("colour by", label(mArrayChoice).c_str())) {
        for (int i = mOpenedScalar ? -1 : 0; i < int(mArrayChoices.size()); ++i) {
            ImGui::PushID(i);
            if (ImGui::Selectable(label(i).c_str(), i == mArrayChoice) && i != mArrayChoice) colourBy(i);
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    tooltip("the scalar shown: each array of the file (a vector's magnitude or one component; a cell array flat per "
            "triangle), as --scalar names it; the colour range follows the data (the range options' rules, not a "
            "fixed --range). A time series: the array of every step, its range over all steps (each step read again "
            "in the background; disabled while its volume loads). Disabled while an optimiser or that reading runs.");
    return mArrayChoice != shown;
}

void ViewerApp::colourBy(int choice)
{
    if (mSeries) {
        startSeriesColouring(choice);
        return;
    }
    mCpuTracer.cancel();  // it reads the field's values
    std::vector<float> shownValues = mField->values;  // shown again when the choice fails
    const core::Association shownOn = mField->valuesOn;
    std::string shownName = mField->name;
    core::ColorScale dataScale;
    try {
        if (choice < 0) {
            mField->values = mOpenedScalar->values;
            mField->valuesOn = mOpenedScalar->on;
            mField->name = mOpenedScalar->name;
        } else {
            core::showArray(*mField, mArrayChoices[std::size_t(choice)].spec, false);
        }
        dataScale = choiceDataScale(choice, mField->values);
    } catch (const std::exception& e) {
        mField->values = std::move(shownValues);
        mField->valuesOn = shownOn;
        mField->name = std::move(shownName);
        mStatus = e.what();
        return;
    }
    showChoice(choice, dataScale);
}

core::ColorScale ViewerApp::choiceDataScale(int choice, const std::vector<float>& data) const
{
    if (choice == mOpenedChoice) return mOpenedDataScale;
    core::ColorScaleRequest request = mOptions.view.colorScaleRequest();
    request.range.reset();  // a range given was the opened scalar's
    try {
        return request.resolve(data);
    } catch (const ValueError&) {  // a log scale over data without a positive value
        request.log = false;
        return request.resolve(data);
    }
}

void ViewerApp::showChoice(int choice, const core::ColorScale& dataScale)
{
    if (mArrayChoice == mOpenedChoice) mOpenedScale = mShading.scale;  // as the panel left it
    mArrayChoice = choice;
    mDataScale = dataScale;
    // The opened scalar gets its own scale again (--range, a view file's, the panel's).
    mShading.scale = choice == mOpenedChoice ? mOpenedScale : mDataScale;
    mRenderer->setMesh(*mField, mNormals);
    mProbe.readScalar(*mField);
    std::printf("inversevis-view: colour by %s, range %g to %g%s\n", mField->name.c_str(), mDataScale.range.lo,
                mDataScale.range.hi, mDataScale.log ? ", log" : "");
    std::fflush(stdout);
    mDirty = true;
}

void ViewerApp::startSeriesColouring(int choice)
{
    auto series = std::make_unique<core::SurfaceSeries>(*mSeries);
    const core::SurfaceLoadOptions load = choiceLoad(choice);
    const std::size_t step = mStep;  // the slider waits for the job
    mCancelJob = false;
    mColouring = std::async(std::launch::async, [this, choice, load, step, series = std::move(series)]() mutable {
        series->chooseScalar(load);
        SeriesSurvey survey = surveySeries(*series, nullptr, &mCancelJob);
        const core::ScopedLogLevel silent(core::LogLevel::Silent);  // the survey has loaded it: nothing new to say
        core::SurfaceField shown = series->load(step);
        return SeriesColouring{std::move(series), std::move(survey), std::move(shown), choice};
    });
    mStatus = "colour by: reading every step of the series...";
}

void ViewerApp::pollSeriesColouring()
{
    if (!mColouring.valid() || mColouring.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    core::ColorScale dataScale;
    SeriesColouring colouring;
    try {
        colouring = mColouring.get();
        if (colouring.survey.meshHashes != mSurvey.meshHashes)
            throw InputError(mSeries->source() + ": a step's geometry changed on disk since the series was opened; "
                                                 "open it again");
        dataScale = choiceDataScale(colouring.choice, colouring.survey.sample);
    } catch (const std::exception& e) {  // a step without the array, a file changed on disk, a cancel
        mStatus = std::string("colour by: ") + e.what();
        return;
    }
    mCpuTracer.cancel();  // it reads the field's values
    mSeries = std::move(colouring.series);
    mSurvey = std::move(colouring.survey);
    core::showStepData(*mField, std::move(colouring.shown));  // the same geometry (its hash)
    mStatus.clear();
    showChoice(colouring.choice, dataScale);
}

core::SurfaceLoadOptions ViewerApp::choiceLoad(int choice) const
{
    core::SurfaceLoadOptions load = mOptions.mesh.load;
    if (choice != mOpenedChoice) {
        load.read = core::MeshReadOptions{mArrayChoices[std::size_t(choice)].spec, "", false};
        load.hotSpots = 0;
    }
    return load;
}

bool ViewerApp::drawPictureSection()
{
    bool changed = false;
    bool framed = mOrbit.framed;
    if (ImGui::Checkbox("frame the picture (F)", &framed)) {
        mAnimation.stop();
        if (framed) mOrbit.frameAgain();
        else mOrbit.framed = false;
        changed = true;
    }
    tooltip("render::frameView each frame: the field of view fitted to the object and the method's whole indirect "
            "region (hull, rings or mirror footprint) with a margin, the eye back on the radius-2.5 sphere; a zoom "
            "or pan ends it");
    ImGui::Text("camera theta %.1f phi %.1f distance %.2f, field of view %.1f", mOrbit.thetaDeg, mOrbit.phiDeg,
                mOrbit.distance, mOrbit.fovYDeg);
    if (tracesOnCpu()) {
        changed |= ImGui::SliderFloat("render scale", &mRenderScale, 0.25f, 1.0f, "%.2f");
        tooltip("fraction of the window's pixels the CPU traces once the camera rests");
        ImGui::Text("traced by the CPU (--tracer); moving: %.0f%% of each side", 100.0 * mCpuTracer.movingScale());
        tooltip("the CPU renderer draws the picture render writes: while the camera moves, as many pixels as keep 12 "
                "frames per second; once it rests, the full picture, shown when done (--tracer gpu: the shaders)");
    } else {
        changed |= traceScaleWidgets(mRenderScale, mInteraction.reduction);
    }
    ImGui::Text("frame %.1f ms (%.1f fps) at %dx%d", mLastFrameMs, mLastFrameMs > 0.0 ? 1000.0 / mLastFrameMs : 0.0,
                mRenderer->width(), mRenderer->height());
    if (mLoaded) ImGui::TextUnformatted(mVolumeText.c_str());
    ImGui::TextDisabled("%s", mGlRenderer.c_str());
    return changed;
}

void ViewerApp::writeWindow(const std::string& path)
{
    const core::Image image = readWindow(mWindow);
    core::writePng(image, path, false);
    std::printf("inversevis-view: wrote %s (window %dx%d, panel %dx%d, picture %dx%d from x %d, %s)\n", path.c_str(),
                image.width(), image.height(), mPanelSize.x, mPanelSize.y, mPicture.width, mPicture.height, mPicture.x,
                mStatus.c_str());
}

int ViewerApp::runInteractive()
{
    setPlaying(mOptions.play);
    int lastWidth = 0, lastHeight = 0, settledFrames = 0;
    while (!glfwWindowShouldClose(mWindow)) {
        const bool busy = mDirty || mLoader || jobRunning() || mAnimation.started() || mRestWanted;
        if (busy) glfwPollEvents();
        else if (mCpuTracer.resting()) glfwWaitEventsTimeout(0.05);  // the CPU's picture takes both cores
        else glfwWaitEventsTimeout(mPlaying ? std::clamp(mNextStepTime - now(), 0.001, 0.25) : 0.25);
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
                traceOnCpu(width, height, mInteraction.moving(now()) || mAnimation.started() || mPlaying);
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
