// ViewerApp: the CPU optimisers the panel starts, in the background, and their results.
#include "viewer_app.h"

#include "viewer_clock.h"


#include <cstdio>

namespace ivis::app {

bool ViewerApp::choosesReadableRule() const
{
    const std::string& key = mMethod->info().readableRuleParameter;
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
        if (mJobName == "optimise view") mViewSet = result.views;
        moveTo(result.state, mMethod == mJobMethod, time);
    } catch (const std::exception& e) {
        mStatus = mJobName + " failed: " + e.what();
    }
    mDirty = true;
}

void ViewerApp::moveTo(const ViewState& view, bool sameMethod, double time)
{
    // Unless the method was changed meanwhile, it takes the view's other parameters (the readable
    // rule) now and its optimised ones ease to the view's.
    if (sameMethod) mMethod = render::withOptimisedParameters(*view.method, render::optimisedParameters(*mMethod));
    mAnimatedMethod = mMethod->name();
    const OrbitCamera to = OrbitCamera::fromCamera(view.camera, false);
    mAnimation = CameraAnimation(mOrbit, sameMethod ? render::optimisedParameters(*mMethod) : std::vector<double>{},
                                 to, sameMethod ? render::optimisedParameters(*view.method) : std::vector<double>{},
                                 time, 1.0);
}

}  // namespace ivis::app
