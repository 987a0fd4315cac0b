/// @file progress_bar.h
/// @brief An Interrupter that draws a one-line progress bar on stderr once an operation has run
///        for a second ("armadillo 2/10, inversevis: viewpoint annealing [####    ] 42%, 3 s, about
///        4 s left"), only when stderr is a terminal and the log level allows Info, and that
///        cancels the operation once Ctrl-C was pressed (interrupt_signal.h).
/// @warning wasInterrupted is safe to call from several threads.
#pragma once

#include <ivis/core/interrupter.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <cstddef>
#include <string>

namespace ivis::core {

/// @brief Terminal progress bar; cancels after SIGINT.
class ProgressBar : public Interrupter {
public:
    /// @brief Draws nothing when @a enabled is false (e.g. --quiet).
    explicit ProgressBar(bool enabled = true);
    /// @brief What the next operations belong to, shown before their names (e.g. "armadillo
    ///        2/10, inversevis"); "" for nothing.
    void setContext(std::string context);
    /// @brief Starts a bar for the operation @a name.
    void start(const char* name = nullptr) override;
    /// @brief Ends the bar (its line cleared).
    void end() override;
    /// @brief Redraws the bar at @a percent (after its first second, as the percentage rises);
    ///        true once an interrupt (Ctrl-C) was requested.
    bool wasInterrupted(int percent = -1) override;

private:
    bool mEnabled;
    std::string mContext;
    std::string mName;
    std::size_t mDrawnWidth = 0;  ///< characters of the line drawn last
    std::chrono::steady_clock::time_point mStart;
    std::atomic<int> mShownPercent{-1};
    std::atomic<bool> mDrawn{false};
    std::mutex mMutex;
};

}  // namespace ivis::core
