// ViewerApp: the runs without a user: --screenshot and --benchmark.
#include "viewer_app.h"

#include "viewer_clock.h"

#include "../frame_video.h"

#include <ivis/core/errors.h>
#include <ivis/core/interrupt_signal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace ivis::app {

int ViewerApp::runHeadlessScreenshot()
{
    waitForScene();
    // A series: every step in turn, as the time slider shows it, one numbered screenshot each,
    // renamed into place together once all are written (Ctrl-C leaves none, as render's frames).
    const std::size_t steps = mSeries ? mSeries->steps().size() : 1;
    core::AtomicFileSet files;
    std::vector<std::string> written;
    // A series' screenshots are one size whatever each step's title, as render's frames.
    const int legendMargin = mSeries && mShowLegend && mField->hasScalar()
                                 ? seriesLegendMargin(*mSeries, legendContent(), mField->name, mOptions.width,
                                                      mOptions.height, mLegendSide)
                                 : 0;
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
        writeScreenshot(files, path, numbered(mOptions.regionPng), legendMargin);
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

}  // namespace ivis::app
