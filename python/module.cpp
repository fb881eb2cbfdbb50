// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module roomcad (its compiled part, _roomcad; python/roomcad/__init__.py re-exports
// it): plans, validation, edits, models and pictures over the same library as the command.
#include <filesystem>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "import/ifc_import.h"
#include "import/sweethome3d_import.h"
#include "python/py_error.h"
#include "python/py_types.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

/// Runs `import_file` (a Sweet Home 3D or IFC import) without the GIL.
/// @return its plan as a roomcad.Plan named after the file, with the import's warnings
template <class ImportFile>
PyPlan imported_plan(const std::filesystem::path& path, ImportFile import_file) {
  std::optional<decltype(import_file())> imported;
  {
    py::gil_scoped_release free;
    imported.emplace(import_file());
  }
  auto model = take(std::move(*imported));
  PyPlan out;
  out.plan = std::move(model.plan);
  out.name = path.stem().string() + ".json";
  out.import_warnings = std::move(model.warnings);
  return out;
}

PyPlan import_home(const std::filesystem::path& path, const std::optional<std::string>& level,
                   double chord_tolerance) {
  Sh3dImportOptions options;
  if (level) options.level = *level;
  options.chord_tolerance = chord_tolerance;
  return imported_plan(path, [&] { return import_sweethome3d_file(path, options); });
}

PyPlan import_ifc(const std::filesystem::path& path) {
  return imported_plan(path, [&] { return import_ifc_file(path); });
}

}  // namespace
}  // namespace roomcad::python

PYBIND11_MODULE(_roomcad, m) {
  using namespace roomcad::python;
  m.doc() = "roomcad: room plans validated exactly, built as exact solids, rendered and drawn.";
  register_error(m);
  register_report(m);
  register_model(m);
  register_plan(m);
  m.def("import_sweethome3d", &import_home, py::arg("path"), py::arg("level") = py::none(),
        py::arg("chord_tolerance") = 0.01,
        "Imports a Sweet Home 3D home (.sh3d archive or Home.xml) as a Plan, as `roomcad\n"
        "import`; plan.import_warnings lists what was approximated or left out.\n"
        "@param level            the name of the one level to import (default: all)\n"
        "@param chord_tolerance  metres: how far an arc wall's chords may stray from the arc\n"
        "@raise roomcad.Error (io_error, parse_error, ... naming the file and element)");
  m.def("import_ifc", &import_ifc, py::arg("path"),
        "Imports an IFC model (.ifc, IFC2X3 or IFC4: storeys, walls, openings, slabs) as a Plan,\n"
        "as `roomcad import`; plan.import_warnings lists what was approximated or left out.\n"
        "@raise roomcad.Error (io_error, parse_error naming the file and line, unsupported)");
}
