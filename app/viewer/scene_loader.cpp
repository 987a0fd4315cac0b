#include "scene_loader.h"

#include <ivis/core/errors.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace ivis::app {

void LoadProgress::start(const char* name)
{
    if (name) setStage(name);
    mPercent = 0;
}

void LoadProgress::end() { mPercent = 100; }

bool LoadProgress::wasInterrupted(int percent)
{
    if (percent >= 0) mPercent = std::min(percent, 100);
    return mCancel;
}

void LoadProgress::setStage(const std::string& stage)
{
    std::lock_guard<std::mutex> lock(mMutex);
    mStage = stage;
}

std::string LoadProgress::stage() const
{
    std::lock_guard<std::mutex> lock(mMutex);
    return mStage;
}

SceneLoader::SceneLoader(const core::SurfaceField& field, const vdb::VolumeOptions& volumeOptions,
                         std::string cachePath, const DenseSliceOptions& sliceOptions)
    : mField(field), mVolumeOptions(volumeOptions), mCachePath(std::move(cachePath)), mSliceOptions(sliceOptions)
{
    mThread = std::thread([this] { run(); });
}

SceneLoader::~SceneLoader()
{
    mProgress.cancel();
    if (mThread.joinable()) mThread.join();
}

void SceneLoader::run()
{
    try {
        const auto start = std::chrono::steady_clock::now();
        auto loaded = std::make_unique<LoadedScene>();
        loaded->cachePath = mCachePath;
        const std::filesystem::path folder = std::filesystem::path(mCachePath).parent_path();
        std::error_code error;
        if (!folder.empty()) std::filesystem::create_directories(folder, error);
        if (error) throw InputError(folder.string() + ": cannot create the cache folder (" + error.message() + ")");
        mProgress.setStage("volume");
        loaded->volume = vdb::loadOrBuildVolume(mField.mesh, mVolumeOptions, mCachePath, &mProgress, &loaded->cacheOutcome);
        if (mProgress.wasInterrupted()) throw Cancelled("loading cancelled");
        mProgress.setStage("CPU scene (BVH, far field)");
        mProgress.wasInterrupted(-1);
        loaded->scene = std::make_unique<render::RenderScene>(mField, loaded->volume);
        mProgress.setStage("GPU volume");
        loaded->slices = buildDenseSlices(*loaded->scene, mSliceOptions, &mProgress);
        loaded->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        mResult = std::move(loaded);
    } catch (...) {
        mError = std::current_exception();
    }
    mFinished = true;
}

std::unique_ptr<LoadedScene> SceneLoader::take()
{
    if (mThread.joinable()) mThread.join();
    if (mError) std::rethrow_exception(mError);
    return std::move(mResult);
}

}  // namespace ivis::app
