#include <ivis/core/interrupt_signal.h>

#include <atomic>
#include <csignal>
#include <initializer_list>

namespace ivis::core {
namespace {

std::atomic<int> gSignal{0};  ///< the signal received, 0 before one

extern "C" void onInterrupt(int signal)
{
    gSignal = signal;
    std::signal(signal, SIG_DFL);  // a second one ends the program at once
}

}  // namespace

void installInterruptHandler()
{
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, onInterrupt);
}

bool interruptRequested() { return gSignal != 0; }

int interruptExitStatus() { return 128 + (gSignal != 0 ? int(gSignal) : SIGINT); }

ScopedInterruptHandler::ScopedInterruptHandler()
{
    gSignal = 0;
    mPrevious = std::signal(SIGINT, onInterrupt);
}

ScopedInterruptHandler::~ScopedInterruptHandler()
{
    std::signal(SIGINT, mPrevious == SIG_ERR ? SIG_DFL : mPrevious);
    gSignal = 0;
}

}  // namespace ivis::core
