// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/mesh_readback_support.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "io/plan_json.h"
#include "mesh/mesh_check.h"
#include "solid/analytic_volume.h"
#include "solid/build_model.h"
#include "support/run_command.h"

namespace roomcad::test {
namespace {

std::vector<std::filesystem::path> example_plan_files() {
  std::vector<std::filesystem::path> plans = example_plans();
  std::vector<std::filesystem::path> homes;
  for (const auto& e :
       std::filesystem::directory_iterator(source_dir() / "examples" / "sweethome3d"))
    if (e.path().extension() == ".json") homes.push_back(e.path());
  std::sort(homes.begin(), homes.end());
  plans.insert(plans.end(), homes.begin(), homes.end());
  return plans;
}

Point3 point3(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

}  // namespace

const std::vector<BuiltExample>& built_examples() {
  static const std::vector<BuiltExample> built = [] {
    std::vector<BuiltExample> out;
    for (const auto& path : example_plan_files()) {
      const Result<Plan> read = read_plan_file(path);
      if (!read) throw std::runtime_error(path.string() + ": does not read: " + read.message());
      out.push_back({path.stem().string(), build_model(*read), analytic_wall_volume(*read)});
    }
    return out;
  }();
  return built;
}

MeshParts all_parts(const Model& model) {
  return {{&model.walls, &model.floor, &model.fixtures}, &model.objects};
}

ExpectedMesh expected_mesh(const Model& model) {
  ExpectedMesh e;
  e.wall_vertices = model.walls.n_vertices();
  e.wall_faces = model.walls.n_faces();
  for (const SolidMesh* mesh : {&model.walls, &model.floor, &model.fixtures}) {
    const std::size_t base = e.vertices.size();
    for (const auto v : mesh->vertices()) e.vertices.push_back(point3(mesh->point(v)));
    const FacePropertyHandles props = face_property_handles(*mesh);
    for (const auto f : mesh->faces()) {
      ExpectedFace& face = e.faces.emplace_back();
      for (const auto v : mesh->fv_range(f)) face.corners.push_back(base + std::size_t(v.idx()));
      const Color c = mesh->property(props.color, f);
      face.color = {c.r, c.g, c.b};
      const int object = mesh->property(props.object, f);
      face.group = object < 0 ? "floor" : model.objects.at(std::size_t(object));
      face.normal = point3(mesh->normal(f));
    }
  }
  return e;
}

std::vector<std::vector<Point3>> wall_polygons(const ReadMesh& read, std::size_t wall_vertices) {
  std::vector<std::vector<Point3>> polygons;
  for (const auto& face : read.faces) {
    if (std::any_of(face.begin(), face.end(), [&](std::size_t v) { return v >= wall_vertices; }))
      continue;
    std::vector<Point3>& p = polygons.emplace_back();
    for (const std::size_t v : face) p.push_back(read.vertices[v]);
  }
  return polygons;
}

double enclosed_volume(const std::vector<std::vector<Point3>>& polygons) {
  if (polygons.empty()) return 0.0;
  const Point3 o = polygons.front().front();  // near the solid: the sum keeps its precision
  auto minus = [&](const Point3& p) { return Point3{p[0] - o[0], p[1] - o[1], p[2] - o[2]}; };
  double six_volume = 0.0;
  for (const auto& polygon : polygons) {
    const Point3 a = minus(polygon[0]);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const Point3 b = minus(polygon[i]), c = minus(polygon[i + 1]);
      six_volume += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
  }
  return six_volume / 6.0;
}

}  // namespace roomcad::test
