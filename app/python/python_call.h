/// @file python_call.h
/// @brief A long call of the engine from Python: the GIL released (other Python threads run), a
///        Ctrl-C in the main thread stopping it within a second as KeyboardInterrupt, and progress
///        reported to an optional Python callable.
#pragma once

#include <ivis/core/interrupter.h>

#include <pybind11/pybind11.h>

#include <functional>

namespace ivis::python {

/// @brief Runs @a work with the GIL released, giving it an interrupter that reports progress to
///        @a progress (None or a callable (stage: str, percent: int)) and cancels on Ctrl-C (when
///        called from Python's main thread).
/// @throw pybind11::error_already_set KeyboardInterrupt when cancelled; what @a work or the callback throws
void runReleased(const std::function<void(core::Interrupter&)>& work, const pybind11::object& progress);

}  // namespace ivis::python
