#include "cpu_tracer.h"

#include <ivis/core/errors.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ivis::app {

render::RenderResult CpuTracer::renderMoving(const render::RenderScene& scene, const core::Camera& camera,
                                             render::RenderOptions options)
{
    cancel();
    options.width = std::max(16, int(std::lround(options.width * mMovingScale)));
    options.height = std::max(16, int(std::lround(options.height * mMovingScale)));
    const auto start = std::chrono::steady_clock::now();
    const double period = std::chrono::duration<double>(start - mLastMoving).count();
    mLastMoving = start;
    render::RenderResult result = render::renderImage(scene, camera, options);
    const double seconds = std::max(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1e-4);
    // The render may take what the period leaves of the frame: the period less the window's own
    // work (the last period less the last render), when the frames follow each other; three
    // quarters of the period after a pause. The time goes with the pixels traced: the side scales
    // with the root of the time ratio, damped (halfway in the logarithm) so that one slow frame
    // does not halve the next.
    const double budget = period < 4.0 * kMovingPeriod
                              ? std::max(kMovingPeriod - (period - mLastSeconds), 0.2 * kMovingPeriod)
                              : 0.75 * kMovingPeriod;
    mLastSeconds = seconds;
    const double ratio = std::clamp(budget / seconds, 0.25, 4.0);
    mMovingScale = std::clamp(float(mMovingScale * std::pow(ratio, 0.25)), kMinMovingScale, kMaxMovingScale);
    return result;
}

void CpuTracer::startResting(const render::RenderScene& scene, const core::Camera& camera,
                             const render::RenderOptions& options, void (*done)())
{
    cancel();
    std::packaged_task<render::RenderResult()> task(
        [&scene, camera, options, this] { return render::renderImage(scene, camera, options, &mCancel); });
    mResting = task.get_future();
    // done() only once the picture is ready (or the render failed): a caller woken by it finds it.
    mWorker = std::thread([task = std::move(task), done]() mutable {
        task();
        if (done) done();
    });
}

std::optional<render::RenderResult> CpuTracer::takeResting()
{
    if (!mResting.valid() || mResting.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    mWorker.join();
    try {
        return mResting.get();
    } catch (const Cancelled&) {
        return std::nullopt;
    }
}

bool CpuTracer::cancel()
{
    if (!mResting.valid()) return false;
    mCancel.raised = true;
    mWorker.join();
    try {
        mResting.get();
    } catch (const Cancelled&) {
    } catch (...) {  // a picture no longer wanted: its error does not matter now
    }
    mCancel.raised = false;
    return true;
}

}  // namespace ivis::app
