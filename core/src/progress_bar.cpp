#include <ivis/core/progress_bar.h>

#include <ivis/core/interrupt_signal.h>
#include <ivis/core/log.h>

#include <cstdio>
#include <unistd.h>

namespace ivis::core {

ProgressBar::ProgressBar(bool enabled)
    : mEnabled(enabled && ::isatty(STDERR_FILENO) && logLevel() <= LogLevel::Info)
{
}

void ProgressBar::start(const char* name)
{
    mName = name ? name : "";
    mStart = std::chrono::steady_clock::now();
    mShownPercent = -1;
    mDrawn = false;
}

void ProgressBar::end()
{
    if (!mDrawn) return;
    std::lock_guard<std::mutex> lock(mMutex);
    std::fprintf(stderr, "\r%-70s\r", "");
    std::fflush(stderr);
    mDrawn = false;
}

bool ProgressBar::wasInterrupted(int percent)
{
    if (interruptRequested()) return true;
    if (!mEnabled || percent < 0 || percent <= mShownPercent) return false;
    if (std::chrono::steady_clock::now() - mStart < std::chrono::seconds(1)) return false;
    std::lock_guard<std::mutex> lock(mMutex);
    if (percent <= mShownPercent) return false;
    mShownPercent = percent;
    const int filled = percent * 40 / 100;
    std::fprintf(stderr, "\r%-10s [%s%s] %3d%%", mName.c_str(), std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(40 - filled), ' ').c_str(), percent);
    std::fflush(stderr);
    mDrawn = true;
    return false;
}

}  // namespace ivis::core
