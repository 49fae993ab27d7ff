// errors.cpp - the exception classes and the translator from ggxcl's.
#include "errors.hpp"

#include <ggxcl/error.hpp>

namespace py = pybind11;

namespace ggxpy {

namespace {

PyObject* invalid_argument = nullptr;
PyObject* device_error = nullptr;
PyObject* build_error = nullptr;
PyObject* device_lost = nullptr;

PyObject* new_class(py::module_& m, const char* name, PyObject* base, const char* doc)
{
    PyObject* type = PyErr_NewExceptionWithDoc((std::string("ggxcl.") + name).c_str(), doc, base, nullptr);
    m.add_object(name, py::reinterpret_borrow<py::object>(type));
    return type;
}

// Raises an instance of `type` with `message` and the attribute `name` = `value`.
void raise_with(PyObject* type, const char* message, const char* name, const std::string& value)
{
    py::object error = py::reinterpret_borrow<py::object>(type)(message);
    error.attr(name) = value;
    PyErr_SetObject(type, error.ptr());
}

} // namespace

void register_errors(py::module_& m)
{
    invalid_argument = new_class(m, "InvalidArgument", PyExc_ValueError,
                                 "A value outside what is allowed; .parameter names the argument.");
    device_error = new_class(m, "DeviceError", PyExc_RuntimeError,
                             "No OpenCL device, none matching the selector, or an OpenCL call that failed.");
    build_error = new_class(m, "BuildError", device_error, "A kernel program failed to build; .log has the build log.");
    device_lost = new_class(m, "DeviceLost", device_error,
                            "The device stopped working during a call; make a new Sampler once it is back.");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const ggxcl::InvalidArgument& e) {
            raise_with(invalid_argument, e.what(), "parameter", e.parameter());
        } catch (const ggxcl::BuildError& e) {
            raise_with(build_error, e.what(), "log", e.log());
        } catch (const ggxcl::DeviceLost& e) {
            PyErr_SetString(device_lost, e.what());
        } catch (const ggxcl::Error& e) {
            PyErr_SetString(device_error, e.what());
        }
    });
}

} // namespace ggxpy
