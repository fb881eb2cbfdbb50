// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad.Model: what Plan.build returns, as numpy arrays, checked and saved as the command does.
#include <array>
#include <filesystem>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "io/mesh_export.h"
#include "io/wall_check_format.h"
#include "mesh/triangulate_face.h"
#include "python/py_error.h"
#include "python/py_types.h"
#include "solid/wall_check.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

/// Appends one mesh's vertices and triangles (indices shifted past those already there).
void add_mesh(PyModel& out, const SolidMesh& mesh, bool is_walls) {
  const auto first = static_cast<std::int32_t>(out.vertices.size() / 3);
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.vertices.insert(out.vertices.end(), {p[0], p[1], p[2]});
  }
  const FacePropertyHandles handles = face_property_handles(mesh);
  // The divergence theorem, relative to a corner of the solid: no cancellation far away.
  const OpenMesh::Vec3d origin =
      mesh.n_vertices() > 0 ? mesh.point(*mesh.vertices_begin()) : OpenMesh::Vec3d(0, 0, 0);
  std::vector<OpenMesh::Vec3d> corners;
  std::vector<std::int32_t> indices;
  for (const auto f : mesh.faces()) {
    corners.clear();
    indices.clear();
    for (const auto v : mesh.fv_range(f)) {
      corners.push_back(mesh.point(v));
      indices.push_back(first + v.idx());
    }
    const int object = mesh.property(handles.object, f);
    const std::string id = object >= 0 ? out.model.objects[static_cast<std::size_t>(object)] : "";
    const std::string kind(to_string(mesh.property(handles.kind, f)));
    for (const std::array<int, 3>& t : triangulate_face(corners, mesh.normal(f))) {
      const OpenMesh::Vec3d& a = corners[t[0]];
      if (is_walls)
        out.volume += (((corners[t[1]] - a) % (corners[t[2]] - a)) | (a - origin)) / 6.0;
      for (const int i : t) out.faces.push_back(indices[static_cast<std::size_t>(i)]);
      out.face_objects.push_back(id);
      out.face_kinds.push_back(kind);
    }
  }
}

}  // namespace

PyModel& triangulated(PyModel& model) {
  if (model.triangulated) return model;
  add_mesh(model, model.model.walls, true);
  add_mesh(model, model.model.floor, false);
  add_mesh(model, model.model.fixtures, false);
  model.triangulated = true;
  return model;
}

void register_model(py::module_& m) {
  py::class_<PyModel>(
      m, "Model",
      "A plan's 3D model (Plan.build): the wall solid, the floor and the fixtures,\n"
      "as triangles. Coordinates in metres, x east, y north, z up.")
      .def_property_readonly(
          "vertices",
          [](PyModel& model) {
            const PyModel& self = triangulated(model);
            py::array_t<double> out(
                {static_cast<py::ssize_t>(self.vertices.size() / 3), py::ssize_t{3}});
            std::copy(self.vertices.begin(), self.vertices.end(), out.mutable_data());
            return out;
          },
          "N x 3 float64 array: the vertices of the walls, then the floor, then the fixtures")
      .def_property_readonly(
          "faces",
          [](PyModel& model) {
            const PyModel& self = triangulated(model);
            py::array_t<std::int32_t> out(
                {static_cast<py::ssize_t>(self.faces.size() / 3), py::ssize_t{3}});
            std::copy(self.faces.begin(), self.faces.end(), out.mutable_data());
            return out;
          },
          "M x 3 int32 array: triangles, counter-clockwise seen from outside")
      .def_property_readonly(
          "face_objects", [](PyModel& m) { return triangulated(m).face_objects; },
          "the id of the object each triangle belongs to ('' for none)")
      .def_property_readonly(
          "face_kinds", [](PyModel& m) { return triangulated(m).face_kinds; },
          "what each triangle is: wall_face, wall_top, wall_bottom, wall_end, jamb,\n"
          "sill, lintel, floor, door, window")
      .def_property_readonly(
          "volume", [](PyModel& m) { return triangulated(m).volume; },
          "the wall solid's volume from its triangles, cubic metres")
      .def(
          "check",
          [](const PyModel& self) {
            std::string json;
            {
              py::gil_scoped_release free;
              json = format_wall_check_json(check_walls(self.model, self.plan));
            }
            return py::module_::import("json").attr("loads")(json);
          },
          "Checks the wall solid as `roomcad build --check` does (closed, 2-manifold, no\n"
          "self-intersection or degenerate face, outward, genus, volume against the plan's\n"
          "analytic volume). @return the dict `--check --format json` prints; ['ok'] is the "
          "verdict.")
      .def(
          "save",
          [](const PyModel& self, const std::filesystem::path& path) {
            const MeshParts parts{{&self.model.walls, &self.model.floor, &self.model.fixtures},
                                  &self.model.objects};
            Status written;
            {
              py::gil_scoped_release free;
              written = write_mesh_file(path, parts);
            }
            require(written);
          },
          py::arg("path"),
          "Writes the model in the format of the extension of `path` (.obj with .mtl beside\n"
          "it, .off, .ply, .stl), atomically: the same bytes as `roomcad build -o path`.\n"
          "@raise roomcad.Error (unsupported, io_error)")
      .def("__repr__", [](const PyModel& self) {
        return "<Model: " + std::to_string(self.model.walls.n_faces()) + " wall faces, " +
               std::to_string(self.model.floor.n_faces()) + " floor faces, " +
               std::to_string(self.model.fixtures.n_faces()) + " fixture faces>";
      });
}

}  // namespace roomcad::python
