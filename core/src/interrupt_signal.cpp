#include <ivis/core/interrupt_signal.h>

#include <atomic>
#include <csignal>

namespace ivis::core {
namespace {

std::atomic<bool> gInterrupted{false};

extern "C" void onInterrupt(int /*signal*/)
{
    gInterrupted = true;
    std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the program at once
}

}  // namespace

void installInterruptHandler() { std::signal(SIGINT, onInterrupt); }

bool interruptRequested() { return gInterrupted; }

ScopedInterruptHandler::ScopedInterruptHandler()
{
    gInterrupted = false;
    mPrevious = std::signal(SIGINT, onInterrupt);
}

ScopedInterruptHandler::~ScopedInterruptHandler()
{
    std::signal(SIGINT, mPrevious == SIG_ERR ? SIG_DFL : mPrevious);
    gInterrupted = false;
}

}  // namespace ivis::core
