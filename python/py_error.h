// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad.Error: how every failure of the library reaches Python, with its code (core/code.h)
// and, when known, the file, line and column.
#pragma once

#include <utility>

#include <pybind11/pybind11.h>

#include "core/error.h"

namespace roomcad::python {

/// A failure on its way to Python: the translator registered by register_error raises it as
/// roomcad.Error.
struct RaisedError {
  Error error;
};

[[noreturn]] inline void raise(Error error) { throw RaisedError{std::move(error)}; }

/// @return the value of `result`. @throws RaisedError with its error.
template <class T>
T take(Result<T>&& result) {
  if (!result) raise(result.error());
  return std::move(result).value();
}

inline void require(const Status& status) {
  if (!status) raise(status.error());
}

/// Defines roomcad.Error in `m` and translates RaisedError, PreconditionError and any other
/// C++ exception (code "internal") into it, so that no input can crash the interpreter.
void register_error(pybind11::module_& m);

}  // namespace roomcad::python
