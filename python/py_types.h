// SPDX-License-Identifier: GPL-3.0-or-later
// The C++ objects behind roomcad.Plan and roomcad.Model, and the functions that register the
// module's classes (one file each).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "mesh/solid_mesh.h"
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/report_format.h"

namespace roomcad::python {

/// roomcad.Plan: a plan, what reading its text found, and the name it was read under.
struct PyPlan {
  Plan plan;
  /// The reader's findings (unknown fields, with lines and columns) while the plan is as read;
  /// emptied by the first edit (validation then finds unknown fields itself).
  std::optional<Report> reading;
  std::string name;  ///< the file's name (drawing titles), "plan" for a plan made in memory
  /// The path it was loaded from, as given: what its report's edit commands name, as the
  /// command's PLAN argument; "PLAN" for a plan made in memory.
  std::string file = "PLAN";
  Report import_warnings;  ///< what an import approximated or left out (import_sweethome3d)
};

/// roomcad.Report: a validation report and how `roomcad validate --format json` prints it
/// (rule findings' ids, the plan file the edit commands name).
struct PyReport {
  Report report;
  ReportFormatOptions format;
  Plan plan;  ///< the plan validated, for to_html and to_bcf
};

/// roomcad.Model: a built model, its plan (for the analytic volume of check()) and its
/// triangles, computed on the first use of an array (so that build() costs what the C++
/// build costs).
struct PyModel {
  Model model;
  Plan plan;
  bool triangulated = false;
  std::vector<double> vertices{};     ///< x, y, z per vertex: walls, then floor, then fixtures
  std::vector<std::int32_t> faces{};  ///< three vertex indices per triangle
  std::vector<std::string> face_objects{};
  std::vector<std::string> face_kinds{};
  double volume = 0.0;  ///< the wall solid's, from its triangles
};

/// Triangulates the model's faces into `model`'s arrays, once (the GIL held: two threads may
/// share a Model). @return `model`. Cost O(faces * corners^2) the first time.
PyModel& triangulated(PyModel& model);

/// The validation gate of build, render, draw and insolation: the plan's first error raised
/// (naming `verb`) unless `force`.
void require_valid(const PyPlan& self, bool force, std::string_view verb);

void register_report(pybind11::module_& m);
void register_model(pybind11::module_& m);
void register_plan(pybind11::module_& m);
/// roomcad.sun, Plan.sun and Plan.insolation (py_daylight.cpp).
void register_daylight(pybind11::module_& m, pybind11::class_<PyPlan>& plan);

}  // namespace roomcad::python
