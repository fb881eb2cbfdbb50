// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad.Report and roomcad.Finding: what Plan.validate returns.
#include "python/py_types.h"

#include <string>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "io/atomic_write.h"
#include "io/bcf_export.h"
#include "io/report_page.h"
#include "python/py_error.h"
#include "validation/report_tally.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

py::object where_of(const Diagnostic& d) {
  if (!d.where) return py::none();
  const auto point = [](Point2 p) { return py::make_tuple(p.x, p.y); };
  if (!d.where->max) return point(d.where->min);
  return py::make_tuple(point(d.where->min), point(*d.where->max));
}

std::vector<Diagnostic> of_severity(const Report& report, Severity severity) {
  std::vector<Diagnostic> out;
  for (const Diagnostic& d : report.items)
    if (d.severity == severity) out.push_back(d);
  return out;
}

}  // namespace

void register_report(py::module_& m) {
  py::class_<Diagnostic>(m, "Finding", "One problem of a plan: an error or a warning.")
      .def_property_readonly(
          "severity",
          [](const Diagnostic& d) { return d.severity == Severity::error ? "error" : "warning"; },
          "'error' or 'warning'")
      .def_property_readonly(
          "code", [](const Diagnostic& d) { return std::string(to_string(d.code)); },
          "its code (docs/plan-format.md, 'Validation codes'), e.g. 'wall_overlap'")
      .def_readonly("objects", &Diagnostic::objects, "the ids of the objects involved")
      .def_readonly("message", &Diagnostic::message, "one sentence a person can act on")
      .def_readonly("fix", &Diagnostic::fix, "a concrete change that removes it ('' if none)")
      .def_property_readonly("where", &where_of,
                             "(x, y) or ((xmin, ymin), (xmax, ymax)) in metres, or None")
      .def_property_readonly(
          "line",
          [](const Diagnostic& d) -> py::object {
            return d.location ? py::object(py::int_(d.location->line)) : py::object(py::none());
          },
          "line in the plan's text, or None")
      .def("__repr__", [](const Diagnostic& d) {
        return (d.severity == Severity::error ? "<error " : "<warning ") +
               std::string(to_string(d.code)) + ": " + d.message + ">";
      });

  py::class_<PyReport>(m, "Report",
                       "What validating a plan found: report.ok, report.errors, report.warnings.")
      .def_property_readonly(
          "ok", [](const PyReport& r) { return r.report.ok(); },
          "True when there is no error (warnings allowed)")
      .def_property_readonly(
          "findings", [](const PyReport& r) { return r.report.items; },
          "every finding, errors first")
      .def_property_readonly(
          "errors", [](const PyReport& r) { return of_severity(r.report, Severity::error); },
          "the findings that are errors")
      .def_property_readonly(
          "warnings", [](const PyReport& r) { return of_severity(r.report, Severity::warning); },
          "the findings that are warnings")
      .def(
          "to_json", [](const PyReport& r) { return format_report_json(r.report, r.format); },
          "The JSON text `roomcad validate --format json` prints for the same plan and rules.")
      .def(
          "to_dict",
          [](const PyReport& r) {
            return py::module_::import("json").attr("loads")(
                format_report_json(r.report, r.format));
          },
          "The object `roomcad validate --format json` prints: {'ok', 'errors', 'warnings'}.")
      .def(
          "to_html",
          [](const PyReport& r, bool picture) {
            const std::vector<std::string> levels = item_levels(r.report, r.plan);
            ReportPageInput page{.title = r.format.plan_file,
                                 .plan = &r.plan,
                                 .report = &r.report,
                                 .item_levels = &levels,
                                 .comparison = nullptr,
                                 .baseline_file = {},
                                 .level = {},
                                 .picture_png = {},
                                 .edits = {},
                                 .repaired = false};
            if (picture) page.picture_png = render_picture_png(r.plan);
            return make_report_page(page);
          },
          py::arg("picture") = false,
          "The page `roomcad report PLAN -o PAGE.html` writes (with picture=True, its picture "
          "of\nthe model; without, as `--picture off`).")
      .def(
          "to_bcf",
          [](const PyReport& r, const std::filesystem::path& path) {
            const std::string archive =
                take(write_bcf_archive({.plan = &r.plan,
                                        .report = &r.report,
                                        .comparison = nullptr,
                                        .plan_file = r.format.plan_file,
                                        .date = file_date_for_bcf(r.format.plan_file)}));
            require(write_file_atomically(path, archive));
          },
          py::arg("path"),
          "Writes the findings as BCF 2.1, the bytes of `roomcad validate PLAN --format bcf -o "
          "PATH`.\n@raise roomcad.Error io_error")
      .def("__str__",
           [](const PyReport& r) { return format_report_text(r.report, false, r.format); })
      .def("__repr__",
           [](const PyReport& r) { return "<Report: " + format_report_summary(r.report) + ">"; });
}

}  // namespace roomcad::python
