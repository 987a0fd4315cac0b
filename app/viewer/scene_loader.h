/// @file scene_loader.h
/// @brief Builds (or reads from the cache) the volume, the CPU scene and the dense slices on a
///        background thread, reporting progress to the UI through a core::Interrupter.
#pragma once

#include "dense_slices.h"

#include <ivis/core/interrupter.h>
#include <ivis/core/surface_field.h>
#include <ivis/render/render_scene.h>
#include <ivis/vdb/surface_volume.h>
#include <ivis/vdb/volume_cache.h>

#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace ivis::app {

/// @brief Progress of the background work as the UI reads it; cancels on request.
/// @warning start/end/wasInterrupted may be called from any thread; snapshot() from the UI thread.
class LoadProgress : public core::Interrupter {
public:
    void start(const char* name = nullptr) override;
    void end() override;
    bool wasInterrupted(int percent = -1) override;
    /// @brief Asks the running operation to stop (it throws Cancelled at its next check).
    void cancel() { mCancel = true; }
    /// @brief Names the next stage when the library does not (e.g. "CPU scene").
    void setStage(const std::string& stage);
    /// @brief Current stage and percent (-1 = unknown).
    std::string stage() const;
    int percent() const { return mPercent; }

private:
    mutable std::mutex mMutex;
    std::string mStage = "starting";
    std::atomic<int> mPercent{-1};
    std::atomic<bool> mCancel{false};
};

/// @brief Everything the viewer needs once loading is done; never moved after construction
///        (the scene refers to the volume).
struct LoadedScene {
    vdb::SurfaceVolume volume;
    std::unique_ptr<render::RenderScene> scene;
    DenseSlices slices;
    vdb::CacheOutcome cacheOutcome = vdb::CacheOutcome::Built;
    std::string cachePath;
    double seconds = 0.0;
};

/// @brief Runs loadOrBuildVolume, RenderScene and buildDenseSlices on its own thread.
class SceneLoader {
public:
    /// @param field normalised surface; must outlive the loader and the LoadedScene
    SceneLoader(const core::SurfaceField& field, const vdb::VolumeOptions& volumeOptions, std::string cachePath,
                const DenseSliceOptions& sliceOptions);
    /// @brief Cancels and joins the thread.
    ~SceneLoader();
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;

    /// @brief True when the thread has finished (with a result or an error).
    bool finished() const { return mFinished; }
    /// @brief The result; rethrows the thread's exception. Call once, after finished().
    std::unique_ptr<LoadedScene> take();
    /// @brief Progress for the panel.
    LoadProgress& progress() { return mProgress; }

private:
    void run();

    const core::SurfaceField& mField;
    vdb::VolumeOptions mVolumeOptions;
    std::string mCachePath;
    DenseSliceOptions mSliceOptions;
    LoadProgress mProgress;
    std::unique_ptr<LoadedScene> mResult;
    std::exception_ptr mError;
    std::atomic<bool> mFinished{false};
    std::thread mThread;
};

}  // namespace ivis::app
