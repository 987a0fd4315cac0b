/// @file interrupt_signal.h
/// @brief Ctrl-C and a batch system's stop for long runs: SIGINT, SIGTERM or SIGHUP sets a flag
///        that the program's interrupters read, so the running operation stops at its next check,
///        removes its temporary files and the program exits with status 128 + the signal (130 for
///        Ctrl-C, 143 for SIGTERM, which Slurm and `timeout` send); a second one ends it at once.
#pragma once

namespace ivis::core {

/// @brief Installs the handler of SIGINT, SIGTERM and SIGHUP (once per process).
void installInterruptHandler();

/// @brief True once one of those signals was received after installInterruptHandler() (or SIGINT
///        while a ScopedInterruptHandler lives).
bool interruptRequested();

/// @brief The exit status of a run the signal stopped: 128 + its number (130 before any).
int interruptExitStatus();

/// @brief While alive, SIGINT sets the flag interruptRequested() reads (cleared when it starts)
///        instead of whatever handled SIGINT before, which is put back at the end: a library call
///        of a host program (the Python module's) stops at its next check.
/// @warning Install it from the thread that receives the host's Ctrl-C (Python's main thread).
class ScopedInterruptHandler {
public:
    /// @brief Clears any earlier request and installs the SIGINT handler (the destructor puts the
    ///        previous one back).
    ScopedInterruptHandler();
    ~ScopedInterruptHandler();
    ScopedInterruptHandler(const ScopedInterruptHandler&) = delete;
    ScopedInterruptHandler& operator=(const ScopedInterruptHandler&) = delete;

private:
    void (*mPrevious)(int);
};

}  // namespace ivis::core
