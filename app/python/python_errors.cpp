#include "python_errors.h"

#include <ivis/core/errors.h>
#include <ivis/core/log.h>

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

namespace ivis::python {
namespace {
std::mutex gLoggedMutex;
std::vector<std::pair<core::LogLevel, std::string>> gLogged;  // guarded by gLoggedMutex
}  // namespace

pybind11::str decodedText(const std::string& text)
{
    return pybind11::reinterpret_steal<pybind11::str>(
        PyUnicode_DecodeUTF8(text.data(), pybind11::ssize_t(text.size()), "replace"));
}

std::string asKeywords(std::string message, std::vector<std::string> options)
{
    std::sort(options.begin(), options.end(),
              [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
    for (const std::string& option : options) {
        std::string keyword = option.substr(2);
        std::replace(keyword.begin(), keyword.end(), '-', '_');
        for (std::size_t at = message.find(option); at != std::string::npos;
             at = message.find(option, at + keyword.size()))
            message.replace(at, option.size(), keyword);
    }
    return message;
}

void sayLogged()
{
    std::vector<std::pair<core::LogLevel, std::string>> logged;
    {
        std::lock_guard<std::mutex> lock(gLoggedMutex);
        logged.swap(gLogged);
    }
    for (const auto& [level, message] : logged) {
        if (level >= core::LogLevel::Warning)
            pybind11::module_::import("warnings")
                .attr("warn")(decodedText(message), pybind11::handle(PyExc_RuntimeWarning), 2);
        else
            pybind11::module_::import("sys").attr("stderr").attr("write")(decodedText("inversevis: " + message + "\n"));
    }
}

void registerErrors(pybind11::module_& module)
{
    // From any thread, the GIL held or not: kept, and said by sayLogged when the call returns.
    core::setLogSink([](core::LogLevel level, const std::string& message) {
        std::lock_guard<std::mutex> lock(gLoggedMutex);
        gLogged.emplace_back(level, message);
    });
    static pybind11::exception<InputError> inputError(module, "InputError", PyExc_ValueError);
    inputError.doc() = "A file or input the engine cannot use: one line naming it and the problem.";
    pybind11::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const InputError& e) {
            PyErr_SetObject(inputError.ptr(), decodedText(e.what()).ptr());
        } catch (const ValueError& e) {
            PyErr_SetObject(PyExc_ValueError, decodedText(e.what()).ptr());
        } catch (const Cancelled&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        }
    });
}

}  // namespace ivis::python
