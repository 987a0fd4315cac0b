/// @file interrupt_signal.h
/// @brief Ctrl-C for long runs: SIGINT sets a flag that the program's interrupters read, so the
///        running operation stops at its next check, removes its temporary files and the program
///        exits with status 130; a second Ctrl-C ends the program at once.
#pragma once

namespace ivis::core {

/// @brief Installs the SIGINT handler (once per process).
void installInterruptHandler();

/// @brief True once SIGINT was received after installInterruptHandler().
bool interruptRequested();

}  // namespace ivis::core
