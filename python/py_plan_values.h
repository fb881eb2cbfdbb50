// SPDX-License-Identifier: GPL-3.0-or-later
// Python values of plan fields as the text set_field reads (plan/field_text.h): numbers,
// (x, y) points, (x, y, z) vectors, lists of points (polygons) and of polygons, strings as they
// are, None to clear an optional field.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace roomcad::python {

/// @return `value` as field text, numbers written so that they read back to the same doubles.
/// @throws RaisedError (usage_error) naming `field` for a value of no field type.
[[nodiscard]] std::string field_value_text(pybind11::handle value, const std::string& field);

}  // namespace roomcad::python
