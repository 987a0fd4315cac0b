/// @file python_errors.h
/// @brief The library's errors as Python exceptions: a bad file or value is inversevis.InputError
///        (a ValueError) or ValueError with the command line's one-line message, a cancelled
///        call KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace ivis::python {

/// @brief @a text (a message, a name read from a file) as a Python str, any bytes that are not
///        UTF-8 replaced by U+FFFD: a file's Latin-1 name must not turn an error into an empty one.
pybind11::str decodedText(const std::string& text);

/// @brief Registers inversevis.InputError and the translation of the library's errors on @a module.
void registerErrors(pybind11::module_& module);

}  // namespace ivis::python
