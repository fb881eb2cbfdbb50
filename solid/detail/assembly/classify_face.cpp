// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/assembly/classify_face.h"

#include <cmath>

namespace roomcad::detail {
namespace {

struct Local {
  double u, w, z;
};

Local to_local(const WallFrame& f, const OpenMesh::Vec3d& p) {
  const double dx = p[0] - f.from.x, dy = p[1] - f.from.y;
  return {dx * f.dir.x + dy * f.dir.y, dx * f.normal.x + dy * f.normal.y, p[2]};
}

double tolerance_for(std::span<const OpenMesh::Vec3d> points) {
  double m = 0.0;
  for (const auto& p : points) m = std::max({m, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  return 1e-6 + 1e-12 * m;
}

// A hole that runs on through a mitre reaches past its u range into the mitre's wedge.
bool is_in_hole(const WallFrame& f, const Hole& h, std::span<const OpenMesh::Vec3d> points,
                double eps) {
  const double u0 = h.through_mitre[0] ? -INFINITY : h.u0 - eps,
               u1 = h.through_mitre[1] ? INFINITY : h.u1 + eps;
  for (const auto& p : points) {
    const Local l = to_local(f, p);
    if (l.u < u0 || l.u > u1 || std::abs(l.w) > f.half + eps || l.z < h.z0 - eps ||
        l.z > h.z1 + eps)
      return false;
  }
  return true;
}

// A face in a hole's box is one of its sides if it lies on the box's boundary plane.
bool label_hole_face(const WallFrame& f, const Hole& h, std::span<const OpenMesh::Vec3d> points,
                     const OpenMesh::Vec3d& n, double eps, FaceKind& kind) {
  auto all_at = [&](auto value, double target) {
    for (const auto& p : points)
      if (std::abs(value(to_local(f, p)) - target) > eps) return false;
    return true;
  };
  const double along = n[0] * f.dir.x + n[1] * f.dir.y;
  if (n[2] > 0.5 && all_at([](Local l) { return l.z; }, h.z0)) kind = FaceKind::sill;
  else if (n[2] < -0.5 && all_at([](Local l) { return l.z; }, h.z1)) kind = FaceKind::lintel;
  else if (along > 0.9 && all_at([](Local l) { return l.u; }, h.u0)) kind = FaceKind::jamb;
  else if (along < -0.9 && all_at([](Local l) { return l.u; }, h.u1)) kind = FaceKind::jamb;
  else return false;
  return true;
}

std::size_t count_inside(const WallFrame& f, std::span<const OpenMesh::Vec3d> points, double eps) {
  std::size_t count = 0;
  for (const auto& p : points) {
    if (p[2] < f.base - eps || p[2] > f.top_max + eps) continue;
    bool inside = true;
    for (std::size_t k = 0; k < 4 && inside; ++k) {
      const Point2 a = f.footprint[k], b = f.footprint[(k + 1) % 4];
      const double ex = b.x - a.x, ey = b.y - a.y;
      const double cross = ex * (p[1] - a.y) - ey * (p[0] - a.x);
      inside = cross >= -eps * std::hypot(ex, ey);
    }
    count += inside;
  }
  return count;
}

}  // namespace

FaceKind wall_face_kind(const WallFrame& f, const OpenMesh::Vec3d& n) {
  if (n[2] > 0.5) return FaceKind::wall_top;
  if (n[2] < -0.5) return FaceKind::wall_bottom;
  const double across = n[0] * f.normal.x + n[1] * f.normal.y;
  return std::abs(across) > 0.9 ? FaceKind::wall_face : FaceKind::wall_end;
}

FaceLabel classify_face(std::span<const OpenMesh::Vec3d> points,
                        std::span<const WallFrame* const> walls, int first_opening_object) {
  const OpenMesh::Vec3d n = polygon_normal(points).normalized();
  const double eps = tolerance_for(points);
  for (const WallFrame* f : walls)
    for (const Hole& h : f->holes) {
      FaceKind kind;
      if (is_in_hole(*f, h, points, eps) && label_hole_face(*f, h, points, n, eps, kind))
        return {kind, first_opening_object + static_cast<int>(h.opening), f->color};
    }
  // Prefer walls whose sides are parallel to a vertical face: a face merged across joined
  // walls (a whole outer side of a grid) is a side, even where it crosses another wall's end.
  const WallFrame* best = walls.empty() ? nullptr : walls.front();
  std::size_t best_count = 0;
  for (const bool parallel_only : {true, false}) {
    for (const WallFrame* f : walls) {
      if (parallel_only && wall_face_kind(*f, n) == FaceKind::wall_end) continue;
      const std::size_t c = count_inside(*f, points, eps);
      if (c > best_count) best = f, best_count = c;
    }
    if (best_count > 0) break;
  }
  if (best == nullptr) return {wall_face_kind(WallFrame{}, n), -1, Color{}};
  return {wall_face_kind(*best, n), static_cast<int>(best->wall), best->color};
}

}  // namespace roomcad::detail
