/// @file interrupter.h
/// @brief Progress and cancel callback for long operations (the shape of OpenVDB's NullInterrupter).
/// @warning wasInterrupted may be called from several threads at once; implementations must cope.
#pragma once

namespace ivis::core {

/// @brief Base interrupter: reports nothing and never interrupts.
class Interrupter {
public:
    virtual ~Interrupter() = default;
    /// @brief Called when a named operation starts.
    virtual void start(const char* /*name*/ = nullptr) {}
    /// @brief Called when the operation ends.
    virtual void end() {}
    /// @brief Progress in percent (or -1 when unknown); returns true to cancel.
    virtual bool wasInterrupted(int /*percent*/ = -1) { return false; }
};

}  // namespace ivis::core
