// SPDX-License-Identifier: GPL-3.0-or-later
// Flattening OpenMesh polygon meshes into the renderer's triangle arrays.
#include "render/scene.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <utility>
#include <vector>

#include "mesh/triangulate_face.h"
#include "render/scene_cells.h"

namespace roomcad {
namespace {

/// A number no scene has had yet.
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

/// The persistent face properties of a mesh, where present.
struct FaceProperties {
  OpenMesh::FPropHandleT<int> object;
  OpenMesh::FPropHandleT<FaceKind> kind;
  OpenMesh::FPropHandleT<Color> color;
  bool has_object = false;
  bool has_kind = false;
  bool has_color = false;

  explicit FaceProperties(const SolidMesh& mesh)
      : has_object(mesh.get_property_handle(object, kObjectProperty)),
        has_kind(mesh.get_property_handle(kind, kKindProperty)),
        has_color(mesh.get_property_handle(color, kColorProperty)) {}
};

/// Newell's normal of a polygon: robust for non-convex and collinear-vertex polygons.
OpenMesh::Vec3d newell_normal(const std::vector<OpenMesh::Vec3d>& p) {
  OpenMesh::Vec3d n(0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const OpenMesh::Vec3d& a = p[i];
    const OpenMesh::Vec3d& b = p[(i + 1) % p.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

glm::vec3 to_vec3f(const OpenMesh::Vec3d& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

/// The centre of the bounding box of the meshes' vertices, or 0 when they have none.
glm::dvec3 centre_of(const std::vector<std::pair<const SolidMesh*, bool>>& meshes) {
  Box3 box = empty_box3();
  for (const auto& entry : meshes)
    for (const auto vh : entry.first->vertices()) {
      const OpenMesh::Vec3d& p = entry.first->point(vh);
      add_point(box, {p[0], p[1], p[2]});
    }
  return is_empty(box) ? glm::dvec3(0.0) : (low_corner(box) + high_corner(box)) / 2.0;
}

/// Opens a new cluster when the current one is full, takes other passes (or there is none).
void start_cluster_if_full(Scene& scene, std::uint8_t passes) {
  const auto first = static_cast<std::uint32_t>(scene.triangle_count());
  if (scene.clusters.empty() || scene.clusters.back().count >= kClusterSize ||
      scene.clusters.back().passes != passes) {
    scene.clusters.push_back(Cluster{.first = first, .count = 0, .bounds = {}, .passes = passes});
  }
}

/// Adds a triangle of world points, stored relative to the scene's origin: the difference is
/// taken in double, so only the (small) result is rounded to float.
void push_triangle(Scene& scene, const std::array<OpenMesh::Vec3d, 3>& corners,
                   const glm::vec3& normal, std::uint8_t passes = kAllPasses) {
  start_cluster_if_full(scene, passes);
  Cluster& cluster = scene.clusters.back();
  for (const OpenMesh::Vec3d& c : corners) {
    const glm::dvec3 world(c[0], c[1], c[2]);
    const glm::vec3 local(world - scene.origin);
    scene.corners.push_back(local);
    add_point(cluster.bounds, glm::dvec3(local));
    add_point(scene.bounds, world);
  }
  scene.normals.push_back(normal);
  ++cluster.count;
}

}  // namespace

void append_mesh(const SolidMesh& mesh, bool two_sided, Scene& scene) {
  scene.revision = next_revision();
  const FaceProperties props(mesh);
  std::vector<OpenMesh::Vec3d> points;
  for (const auto fh : mesh.faces()) {
    if (mesh.has_face_status() && mesh.status(fh).deleted()) continue;
    points.clear();
    for (const auto vh : mesh.fv_range(fh)) points.push_back(mesh.point(vh));
    const OpenMesh::Vec3d normal = newell_normal(points);
    const double length = normal.norm();
    if (points.size() < 3 || !(length > 0.0)) continue;  // degenerate: nothing to draw
    const glm::vec3 unit = to_vec3f(normal / length);
    const auto triangles = triangulate_face(points, normal);
    const std::size_t before = scene.triangle_count();
    for (const auto& t : triangles) {
      push_triangle(scene, {points[t[0]], points[t[1]], points[t[2]]}, unit);
    }
    const std::size_t added = scene.triangle_count() - before;
    scene.objects.insert(scene.objects.end(), added,
                         props.has_object ? mesh.property(props.object, fh) : -1);
    scene.kinds.insert(scene.kinds.end(), added,
                       props.has_kind ? mesh.property(props.kind, fh) : FaceKind::wall_face);
    scene.colors.insert(scene.colors.end(), added,
                        props.has_color ? mesh.property(props.color, fh) : Color{0x80, 0x80, 0x80});
    scene.two_sided.insert(scene.two_sided.end(), added, two_sided ? 1 : 0);
  }
}

void append_triangles(std::span<const glm::dvec3> corners, Color color, FaceKind kind,
                      std::uint8_t passes, Scene& scene) {
  scene.revision = next_revision();
  for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
    const glm::dvec3 n = glm::cross(corners[i + 1] - corners[i], corners[i + 2] - corners[i]);
    if (!(glm::length(n) > 0.0)) continue;  // degenerate: nothing to draw
    std::array<OpenMesh::Vec3d, 3> points;
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3& p = corners[i + static_cast<std::size_t>(c)];
      points[static_cast<std::size_t>(c)] = OpenMesh::Vec3d(p.x, p.y, p.z);
    }
    push_triangle(scene, points, glm::vec3(glm::normalize(n)), passes);
    scene.objects.push_back(-1);
    scene.kinds.push_back(kind);
    scene.colors.push_back(color);
    scene.two_sided.push_back(0);
  }
}

std::optional<Box3> pass_bounds(const Scene& scene, std::uint8_t passes) {
  Box3 box = empty_box3();
  bool all = true;
  for (const Cluster& c : scene.clusters) {
    if ((c.passes & passes) != passes) {
      all = false;
    } else if (!is_empty(c.bounds)) {
      add_point(box, low_corner(c.bounds));
      add_point(box, high_corner(c.bounds));
    }
  }
  if (all) return std::nullopt;
  return box;
}

Box3 model_bounds(const Scene& scene) {
  const std::optional<Box3> local = pass_bounds(scene, kAllPasses);
  if (!local) return scene.bounds;
  Box3 box = empty_box3();
  if (is_empty(*local)) return box;
  add_point(box, low_corner(*local) + scene.origin);
  add_point(box, high_corner(*local) + scene.origin);
  return box;
}

Scene flatten_model(const Model& model, const Parts& parts) {
  std::vector<std::pair<const SolidMesh*, bool>> meshes;  // and whether two-sided
  if (parts.walls) meshes.emplace_back(&model.walls, false);
  if (parts.floor) meshes.emplace_back(&model.floor, false);
  if (parts.fixtures) meshes.emplace_back(&model.fixtures, true);
  Scene scene;
  scene.origin = centre_of(meshes);
  for (const auto& [mesh, two_sided] : meshes) append_mesh(*mesh, two_sided, scene);
  if (!model.cells.empty() && parts.walls && (model.slabs_built || !model.cells.uses_slabs))
    scene.cells = std::make_shared<const SceneCells>(index_cells(model.cells, scene));
  return scene;
}

}  // namespace roomcad
