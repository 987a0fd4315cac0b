#include "python_errors.h"

#include <ivis/core/errors.h>

namespace ivis::python {

pybind11::str decodedText(const std::string& text)
{
    return pybind11::reinterpret_steal<pybind11::str>(
        PyUnicode_DecodeUTF8(text.data(), pybind11::ssize_t(text.size()), "replace"));
}

void registerErrors(pybind11::module_& module)
{
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
