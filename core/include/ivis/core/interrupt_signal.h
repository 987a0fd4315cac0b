/// @file interrupt_signal.h
/// @brief Ctrl-C for long runs: SIGINT sets a flag that the program's interrupters read, so the
///        running operation stops at its next check, removes its temporary files and the program
///        exits with status 130; a second Ctrl-C ends the program at once.
#pragma once

namespace ivis::core {

/// @brief Installs the SIGINT handler (once per process).
void installInterruptHandler();

/// @brief True once SIGINT was received after installInterruptHandler() (or while a
///        ScopedInterruptHandler lives).
bool interruptRequested();

/// @brief While alive, SIGINT sets the flag interruptRequested() reads (cleared when it starts)
///        instead of whatever handled SIGINT before, which is put back at the end: a library call
///        of a host program (the Python module's) stops at its next check.
/// @warning Install it from the thread that receives the host's Ctrl-C (Python's main thread).
class ScopedInterruptHandler {
public:
    ScopedInterruptHandler();
    ~ScopedInterruptHandler();
    ScopedInterruptHandler(const ScopedInterruptHandler&) = delete;
    ScopedInterruptHandler& operator=(const ScopedInterruptHandler&) = delete;

private:
    void (*mPrevious)(int);
};

}  // namespace ivis::core
