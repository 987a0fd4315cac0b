/// @file cpu_tracer.h
/// @brief The viewer's picture traced by the CPU renderer (render::renderImage, the picture
///        `inversevis render` writes), for machines whose OpenGL is software: while the camera
///        moves, at the size that keeps kMovingPeriod between frames (VTK's desired update rate); once it
///        rests, at full size in the background, shown when it is done (progressive refinement).
#pragma once

#include <ivis/core/camera.h>
#include <ivis/core/interrupter.h>
#include <ivis/render/render_scene.h>
#include <ivis/render/renderer.h>

#include <atomic>
#include <chrono>
#include <future>
#include <optional>
#include <thread>

namespace ivis::app {

/// @brief Moving frames on the calling thread, resting pictures on a background one.
/// @note One caller thread; the scene given must outlive the resting picture (cancel() first).
class CpuTracer {
public:
    /// Seconds from one frame to the next aimed at while the camera moves (12 frames per second).
    static constexpr double kMovingPeriod = 1.0 / 12.0;
    /// Least and greatest fraction of the picture's side traced while the camera moves.
    static constexpr float kMinMovingScale = 0.05f;
    static constexpr float kMaxMovingScale = 1.0f;

    CpuTracer() = default;
    ~CpuTracer() { cancel(); }
    CpuTracer(const CpuTracer&) = delete;
    CpuTracer& operator=(const CpuTracer&) = delete;

    /// @brief Cancels the resting picture, then renders @a options' picture now with each side
    ///        scaled by movingScale(), which it then adapts to the time from the last moving frame
    ///        (the window's whole frame) and to this render's time.
    /// @throw what renderImage throws
    render::RenderResult renderMoving(const render::RenderScene& scene, const core::Camera& camera,
                                      render::RenderOptions options);
    /// @brief Starts the full-size picture of @a options in the background (cancelling one running);
    ///        the background thread calls @a done (if any) once the picture is ready or cancelled.
    void startResting(const render::RenderScene& scene, const core::Camera& camera, const render::RenderOptions& options,
                      void (*done)() = nullptr);
    /// @brief The resting picture once it is done (once); nothing while it runs or when none was started.
    /// @throw what its render threw (not Cancelled: a cancelled picture is dropped)
    std::optional<render::RenderResult> takeResting();
    /// @brief True while a resting picture is being rendered.
    bool resting() const { return mResting.valid(); }
    /// @brief Stops the resting picture and waits for it (before the scene it reads changes).
    /// @return true when one was running (its picture is not shown)
    bool cancel();
    /// @brief The fraction of each side the next moving frame traces.
    float movingScale() const { return mMovingScale; }

private:
    /// Cancels the render it is given to when its flag is raised.
    class CancelFlag : public core::Interrupter {
    public:
        std::atomic<bool> raised{false};
        bool wasInterrupted(int) override { return raised.load(); }
    };

    float mMovingScale = 0.15f;
    std::chrono::steady_clock::time_point mLastMoving;  ///< when the last moving frame started
    double mLastSeconds = 0.0;                          ///< the last moving frame's render time
    CancelFlag mCancel;
    std::future<render::RenderResult> mResting;  ///< the resting picture, while it is not taken
    std::thread mWorker;                         ///< the thread rendering it (joined once it is done)
};

}  // namespace ivis::app
