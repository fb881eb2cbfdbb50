// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/py_plan_values.h"

#include <vector>

#include <fmt/format.h>

#include "plan/field_text.h"
#include "python/py_error.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

bool is_number(py::handle v) {
  if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v)) return false;
  return PyFloat_Check(v.ptr()) || PyLong_Check(v.ptr()) ||
         PyObject_HasAttrString(v.ptr(), "__float__");
}

bool is_sequence(py::handle v) {
  return !py::isinstance<py::str>(v) && !py::isinstance<py::bytes>(v) && PySequence_Check(v.ptr());
}

[[noreturn]] void wrong_value(const std::string& field, py::handle value) {
  raise(Error{Code::usage_error,
              fmt::format("field '{}': {} is not a number, a point (x, y), a vector (x, y, z), a "
                          "list of points, a string or None",
                          field, py::repr(value).cast<std::string>())});
}

Point2 point_of(py::handle v, const std::string& field) {
  if (!is_sequence(v) || py::len(v) != 2) wrong_value(field, v);
  const py::sequence s = py::reinterpret_borrow<py::sequence>(v);
  if (!is_number(s[0]) || !is_number(s[1])) wrong_value(field, v);
  return {s[0].cast<double>(), s[1].cast<double>()};
}

Polygon polygon_of(py::handle v, const std::string& field) {
  Polygon polygon;
  for (const py::handle corner : py::reinterpret_borrow<py::sequence>(v))
    polygon.push_back(point_of(corner, field));
  return polygon;
}

}  // namespace

std::string field_value_text(py::handle value, const std::string& field) {
  using field_text_detail::value_text;
  if (value.is_none()) return std::string(kNoValue);
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (is_number(value)) return value_text(value.cast<double>());
  if (!is_sequence(value)) wrong_value(field, value);
  const py::sequence items = py::reinterpret_borrow<py::sequence>(value);
  if (py::len(items) == 0) return value_text(Polygon{});
  if (is_number(items[0])) {
    if (py::len(items) == 2) return value_text(point_of(items, field));
    if (py::len(items) != 3 || !is_number(items[1]) || !is_number(items[2]))
      wrong_value(field, value);
    return value_text(
        Vec3{items[0].cast<double>(), items[1].cast<double>(), items[2].cast<double>()});
  }
  const py::object first = items[0];
  if (is_sequence(first) && py::len(first) > 0 && is_number(py::sequence(first)[0]))
    return value_text(polygon_of(items, field));
  std::vector<Polygon> polygons;
  for (const py::handle polygon : items) {
    if (!is_sequence(polygon)) wrong_value(field, value);
    polygons.push_back(polygon_of(polygon, field));
  }
  return value_text(polygons);
}

}  // namespace roomcad::python
