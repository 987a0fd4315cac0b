/// @file python_errors.h
/// @brief The library's errors as Python exceptions: a bad file or value is inversevis.InputError
///        (a ValueError) or ValueError with the command line's one-line message, a cancelled
///        call KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

namespace ivis::python {

/// @brief Registers inversevis.InputError and the translation of the library's errors on @a module.
void registerErrors(pybind11::module_& module);

}  // namespace ivis::python
