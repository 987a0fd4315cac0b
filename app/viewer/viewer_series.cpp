// ViewerApp: the time series: showing a step, the time slider, playing.
#include "viewer_app.h"

#include "viewer_clock.h"

#include <ivis/core/errors.h>

#include <algorithm>
#include <cstdio>

namespace ivis::app {

void ViewerApp::showStep(std::size_t step)
{
    IVIS_CHECK(mSeries && step < mSeries->steps().size() && !jobRunning());
    core::SurfaceField field = mSeries->load(step);
    stopCpuPicture();  // it reads the field and the scene
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
        mVertices = std::make_unique<core::ClusteredVertices>(mField->mesh.positions);
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

}  // namespace ivis::app
