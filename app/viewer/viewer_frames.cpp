// ViewerApp: one frame of the picture: its camera framed, drawn by the shaders or by the CPU.
#include "viewer_app.h"

#include "viewer_clock.h"

#include <ivis/core/errors.h>
#include <ivis/render/framing.h>

namespace ivis::app {

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
                    : render::fitCamera(camera, render::offsetMeshExtent(*mVertices, camera, 0.0), aspect);
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
        mCpuTracer.startResting(*mLoaded->scene, mOrbit.camera(), cpuOptions(width, height), glfwPostEmptyEvent);
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

bool ViewerApp::cameraMovesForCpu() const
{
    return mInteraction.movingBeforeCancellableRest(now()) || mAnimation.started();
}

void ViewerApp::stopCpuPicture()
{
    if (mCpuTracer.cancel()) mRestWanted = true;
}

}  // namespace ivis::app
