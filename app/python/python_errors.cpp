#include "python_errors.h"

#include <ivis/core/errors.h>

namespace ivis::python {

void registerErrors(pybind11::module_& module)
{
    static pybind11::exception<InputError> inputError(module, "InputError", PyExc_ValueError);
    inputError.doc() = "A file or input the engine cannot use: one line naming it and the problem.";
    pybind11::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const InputError& e) {
            inputError(e.what());
        } catch (const ValueError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const Cancelled&) {
            PyErr_SetNone(PyExc_KeyboardInterrupt);
        }
    });
}

}  // namespace ivis::python
