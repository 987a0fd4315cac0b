/// @file python_errors.h
/// @brief The library's errors as Python exceptions: a bad file or value is inversevis.InputError
///        (a ValueError) or ValueError with the command line's one-line message, a cancelled
///        call KeyboardInterrupt; and its notes and warnings said in Python, not on file descriptor 2.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace ivis::python {

/// @brief @a text (a message, a name read from a file) as a Python str, any bytes that are not
///        UTF-8 replaced by U+FFFD: a file's Latin-1 name must not turn an error into an empty one.
pybind11::str decodedText(const std::string& text);

/// @brief @a message with each command-line option of @a options ("--range-percentile") named as
///        the Python keyword of the same name ("range_percentile"), the longest first so that none
///        is cut inside another: a library message said to a Python caller.
std::string asKeywords(std::string message, std::vector<std::string> options);

/// @brief Registers inversevis.InputError and the translation of the library's errors on @a module,
///        and keeps what the library logs for sayLogged.
void registerErrors(pybind11::module_& module);

/// @brief Says in Python what the library logged since the last call (the GIL held): a warning as a
///        Python RuntimeWarning (the warnings module shows, filters or raises it), a note on sys.stderr
///        ("inversevis: ..."), where a notebook shows it.
/// @throw pybind11::error_already_set when a warnings filter turns a warning into an error
void sayLogged();

}  // namespace ivis::python
