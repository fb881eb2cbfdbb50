// SPDX-License-Identifier: GPL-3.0-or-later
// Test meshes and the CGAL AABB-tree ray caster used as the exact reference.
#include "scene_support.h"

#include <cmath>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "mesh/triangulate_face.h"

namespace roomcad::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 to_point(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

K::Ray_3 to_ray(const glm::dvec3& o, const glm::dvec3& d) {
  return {K::Point_3(o.x, o.y, o.z), K::Vector_3(d.x, d.y, d.z)};
}

}  // namespace

void add_face(SolidMesh& mesh, const std::vector<glm::dvec3>& points, int object, FaceKind kind,
              Color color) {
  OpenMesh::FPropHandleT<int> object_prop;
  OpenMesh::FPropHandleT<FaceKind> kind_prop;
  OpenMesh::FPropHandleT<Color> color_prop;
  if (!mesh.get_property_handle(object_prop, kObjectProperty)) {
    mesh.add_property(object_prop, kObjectProperty);
    mesh.add_property(kind_prop, kKindProperty);
    mesh.add_property(color_prop, kColorProperty);
  }
  mesh.get_property_handle(kind_prop, kKindProperty);
  mesh.get_property_handle(color_prop, kColorProperty);
  std::vector<SolidMesh::VertexHandle> vertices;
  for (const glm::dvec3& p : points) vertices.push_back(mesh.add_vertex({p.x, p.y, p.z}));
  const auto face = mesh.add_face(vertices);
  mesh.property(object_prop, face) = object;
  mesh.property(kind_prop, face) = kind;
  mesh.property(color_prop, face) = color;
}

void add_box(SolidMesh& mesh, const glm::dvec3& a, const glm::dvec3& b, int object, Color color) {
  auto p = [&](int i) {  // corner i: bit 0 x, bit 1 y, bit 2 z
    return glm::dvec3((i & 1) ? b.x : a.x, (i & 2) ? b.y : a.y, (i & 4) ? b.z : a.z);
  };
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const FaceKind kinds[6] = {FaceKind::wall_bottom, FaceKind::wall_top, FaceKind::wall_face,
                             FaceKind::wall_face,   FaceKind::wall_end, FaceKind::wall_end};
  for (int f = 0; f < 6; ++f) {
    add_face(mesh, {p(faces[f][0]), p(faces[f][1]), p(faces[f][2]), p(faces[f][3])}, object,
             kinds[f], color);
  }
}

void add_floor(SolidMesh& mesh, const glm::dvec2& a, const glm::dvec2& b, int object, Color color) {
  add_face(mesh, {{a.x, a.y, 0.0}, {b.x, a.y, 0.0}, {b.x, b.y, 0.0}, {a.x, b.y, 0.0}}, object,
           FaceKind::floor, color);
}

struct RayCaster::Tree {
  Triangles triangles;
  std::vector<int> objects;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree;
};

RayCaster::RayCaster(const std::vector<const SolidMesh*>& meshes)
    : tree_(std::make_unique<Tree>()) {
  for (const SolidMesh* mesh : meshes) {
    OpenMesh::FPropHandleT<int> object_prop;
    const bool has_object = mesh->get_property_handle(object_prop, kObjectProperty);
    for (const auto fh : mesh->faces()) {
      std::vector<OpenMesh::Vec3d> points;
      for (const auto vh : mesh->fv_range(fh)) points.push_back(mesh->point(vh));
      const OpenMesh::Vec3d normal = (points[1] - points[0]) % (points[2] - points[0]);
      for (const auto& t : triangulate_face(points, normal)) {
        tree_->triangles.emplace_back(to_point(points[t[0]]), to_point(points[t[1]]),
                                      to_point(points[t[2]]));
        tree_->objects.push_back(has_object ? mesh->property(object_prop, fh) : -1);
      }
    }
  }
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
}

RayCaster::~RayCaster() = default;

int RayCaster::first_object(const glm::dvec3& origin, const glm::dvec3& direction) const {
  const auto hit = tree_->tree.first_intersected_primitive(to_ray(origin, direction));
  if (!hit) return -1;
  return tree_->objects[static_cast<std::size_t>(*hit - tree_->triangles.cbegin())];
}

bool RayCaster::is_blocked(const glm::dvec3& origin, const glm::dvec3& direction) const {
  return tree_->tree.do_intersect(to_ray(origin, direction));
}

Camera look_from(const glm::dvec3& eye, const glm::dvec3& target, double fov_deg,
                 double view_height, const glm::dvec3& up) {
  Camera c;
  c.id = "test";
  c.projection = view_height > 0.0 ? Projection::orthographic : Projection::perspective;
  c.eye = {eye.x, eye.y, eye.z};
  c.target = {target.x, target.y, target.z};
  c.up = {up.x, up.y, up.z};
  c.fov_deg = fov_deg;
  c.view_height = view_height;
  return c;
}

PixelRay pixel_ray(const CameraMatrices& cam, int width, int height, double x, double y) {
  const glm::dmat4 inverse = glm::inverse(cam.view_projection);
  const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / height * 2.0;
  const glm::dvec4 a = inverse * glm::dvec4(nx, ny, 1.0, 1.0);  // on the near plane
  const glm::dvec4 b = inverse * glm::dvec4(nx, ny, 0.5, 1.0);  // further on
  const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
  return {pa, glm::normalize(pb - pa)};
}

bool is_uniform_around(const std::vector<int>& values, int width, int height, int x, int y,
                       int radius) {
  const int v = values[static_cast<std::size_t>(y) * width + x];
  for (int yy = std::max(0, y - radius); yy <= std::min(height - 1, y + radius); ++yy)
    for (int xx = std::max(0, x - radius); xx <= std::min(width - 1, x + radius); ++xx)
      if (values[static_cast<std::size_t>(yy) * width + xx] != v) return false;
  return true;
}

int count_bad_depths(const FloatImage& depth) {
  int bad = 0;
  for (const float d : depth.values) bad += !(std::isfinite(d) && d >= 0.0f);
  return bad;
}

}  // namespace roomcad::test
