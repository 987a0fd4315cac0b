#include <ivis/core/progress_bar.h>

#include <ivis/core/interrupt_signal.h>
#include <ivis/core/log.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace ivis::core {

ProgressBar::ProgressBar(bool enabled)
    : mEnabled(enabled && ::isatty(STDERR_FILENO) && logLevel() <= LogLevel::Info), mStart(std::chrono::steady_clock::now())
{
}

namespace {

/// "42 s", "3 min 5 s", "1 h 2 min".
std::string duration(double seconds)
{
    const long s = long(seconds + 0.5);
    if (s < 60) return std::to_string(s) + " s";
    if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
    return std::to_string(s / 3600) + " h " + std::to_string(s / 60 % 60) + " min";
}

}  // namespace

void ProgressBar::setContext(std::string context)
{
    std::lock_guard<std::mutex> lock(mMutex);
    mContext = std::move(context);
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
    std::fprintf(stderr, "\r%s\r", std::string(mDrawnWidth, ' ').c_str());
    std::fflush(stderr);
    mDrawn = false;
    mDrawnWidth = 0;
}

bool ProgressBar::wasInterrupted(int percent)
{
    if (interruptRequested()) return true;
    if (!mEnabled || percent < 0 || percent <= mShownPercent) return false;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    if (elapsed < 1.0) return false;
    std::lock_guard<std::mutex> lock(mMutex);
    if (percent <= mShownPercent) return false;
    mShownPercent = percent;
    const int filled = std::min(percent, 100) * 30 / 100;
    std::string line = (mContext.empty() ? "" : mContext + ": ") + (mName.empty() ? "" : mName + " ") + "[" + std::string(std::size_t(filled), '#') +
                       std::string(std::size_t(30 - filled), ' ') + "] " + std::to_string(percent) + "%, " +
                       duration(elapsed);
    if (percent > 0 && percent < 100) line += ", about " + duration(elapsed * (100 - percent) / percent) + " left";
    const std::size_t width = line.size();
    if (width < mDrawnWidth) line += std::string(mDrawnWidth - width, ' ');  // cover a longer previous line
    std::fprintf(stderr, "\r%s", line.c_str());
    std::fflush(stderr);
    mDrawnWidth = std::max(mDrawnWidth, width);
    mDrawn = true;
    return false;
}

}  // namespace ivis::core
