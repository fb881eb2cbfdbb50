// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/py_error.h"

#include <exception>
#include <new>
#include <string>

namespace py = pybind11;

namespace roomcad::python {
namespace {

PyObject* error_type = nullptr;  // roomcad.Error, alive as long as the module

/// Sets roomcad.Error(message) with .code, .file, .line and .column as the pending exception.
void set_error(const Error& error) {
  py::gil_scoped_acquire gil;
  py::object type = py::reinterpret_borrow<py::object>(error_type);
  py::object exception = type(error.message);
  exception.attr("code") = std::string(to_string(error.code));
  const bool located = error.location.has_value();
  exception.attr("file") = located && !error.location->file.empty()
                               ? py::object(py::str(error.location->file))
                               : py::object(py::none());
  exception.attr("line") = located && error.location->line > 0
                               ? py::object(py::int_(error.location->line))
                               : py::object(py::none());
  exception.attr("column") = located && error.location->column > 0
                                 ? py::object(py::int_(error.location->column))
                                 : py::object(py::none());
  PyErr_SetObject(error_type, exception.ptr());
}

}  // namespace

void register_error(py::module_& m) {
  error_type = PyErr_NewExceptionWithDoc(
      "roomcad.Error",
      "A failure of roomcad: .code is a name of the project's error vocabulary (usage_error,\n"
      "io_error, parse_error, invalid_value, not_buildable, edit_refused, ...); .file, .line\n"
      "and .column say where, when known (else None).",
      PyExc_Exception, nullptr);
  m.attr("Error") = py::reinterpret_borrow<py::object>(error_type);
  py::register_exception_translator([](std::exception_ptr pending) {
    try {
      if (pending) std::rethrow_exception(pending);
    } catch (const RaisedError& e) {
      set_error(e.error);
    } catch (const PreconditionError& e) {
      set_error(e.error());
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (a wrong argument type): TypeError, ValueError
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "roomcad: out of memory");
    } catch (const std::exception& e) {
      set_error(Error{Code::internal, e.what()});
    }
  });
}

}  // namespace roomcad::python
