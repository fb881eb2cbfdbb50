// SPDX-License-Identifier: GPL-3.0-or-later
#include "daylight/sun_blockers.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "mesh/triangulate_face.h"

namespace roomcad {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Traits = CGAL::AABB_traits<K, Primitive>;
using TriangleTree = CGAL::AABB_tree<Traits>;

K::Point_3 point(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

void add_polygon(const std::vector<OpenMesh::Vec3d>& corners, const OpenMesh::Vec3d& normal,
                 Triangles& out) {
  for (const auto& t : triangulate_face(corners, normal))
    out.emplace_back(point(corners[t[0]]), point(corners[t[1]]), point(corners[t[2]]));
}

void add_solid(const SolidMesh& solid, Triangles& out) {
  std::vector<OpenMesh::Vec3d> corners;
  for (const auto f : solid.faces()) {
    if (solid.has_face_status() && solid.status(f).deleted()) continue;
    corners.clear();
    for (const auto v : solid.fv_range(f)) corners.push_back(solid.point(v));
    if (corners.size() >= 3) add_polygon(corners, solid.calc_face_normal(f), out);
  }
}

/// The prism over the outline: its floor, its roof and a quad per side.
void add_prism(const Obstruction& o, Triangles& out) {
  std::vector<OpenMesh::Vec3d> floor, roof;
  for (const Point2& p : o.outline) {
    floor.emplace_back(p.x, p.y, o.base);
    roof.emplace_back(p.x, p.y, o.base + o.height);
  }
  add_polygon(floor, {0, 0, 1}, out);
  add_polygon(roof, {0, 0, 1}, out);
  for (std::size_t i = 0; i < floor.size(); ++i) {
    const std::size_t j = (i + 1) % floor.size();
    out.emplace_back(point(floor[i]), point(floor[j]), point(roof[j]));
    out.emplace_back(point(floor[i]), point(roof[j]), point(roof[i]));
  }
}

/// Traversal that stops at the first triangle which blocks (see SunBlockers::blocks).
class FirstBlocker {
 public:
  explicit FirstBlocker(const K::Ray_3& ray) : ray_(ray) {}
  [[nodiscard]] bool go_further() const { return !blocked_; }
  void intersection(const K::Ray_3&, const Primitive& p) {
    const K::Triangle_3& t = p.datum();
    if (CGAL::orientation(t[0], t[1], t[2], ray_.source()) == CGAL::COPLANAR) return;
    if (CGAL::do_intersect(ray_, t)) blocked_ = true;
  }
  template <class Node>
  [[nodiscard]] bool do_intersect(const K::Ray_3&, const Node& node) const {
    return CGAL::do_intersect(ray_, node.bbox());
  }
  [[nodiscard]] bool blocked() const { return blocked_; }

 private:
  const K::Ray_3& ray_;
  bool blocked_ = false;
};

}  // namespace

struct SunBlockers::Tree {
  Triangles triangles;
  TriangleTree tree;
};

SunBlockers::SunBlockers(const SolidMesh& solid, const std::vector<Obstruction>& obstructions)
    : tree_(std::make_unique<Tree>()) {
  add_solid(solid, tree_->triangles);
  for (const Obstruction& o : obstructions) add_prism(o, tree_->triangles);
  std::erase_if(tree_->triangles, [](const K::Triangle_3& t) { return t.is_degenerate(); });
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
}

SunBlockers::~SunBlockers() = default;
SunBlockers::SunBlockers(SunBlockers&&) noexcept = default;
SunBlockers& SunBlockers::operator=(SunBlockers&&) noexcept = default;

bool SunBlockers::blocks(const Vec3& from, const Vec3& direction) const {
  if (tree_->triangles.empty()) return false;
  const K::Ray_3 ray({from.x, from.y, from.z}, K::Vector_3(direction.x, direction.y, direction.z));
  FirstBlocker traversal(ray);
  tree_->tree.traversal(ray, traversal);
  return traversal.blocked();
}

std::size_t SunBlockers::size() const { return tree_->triangles.size(); }

}  // namespace roomcad
