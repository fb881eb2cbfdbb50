// SPDX-License-Identifier: GPL-3.0-or-later
// Polygons on an axis plane for the tests of a plane's faces (grid_faces, lone_faces): an
// axis plane, rectangles and corner-cut rectangles on it as contributions, and the area of the
// faces found, per side and owner.
#pragma once

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail {

// An axis plane x[k] = 0 (normal +e_k) and rectangles on it in its view axes (i, j).
struct AxisPlane {
  PlaneSet set;
  int k, i, j;
  PlaneId plane;

  explicit AxisPlane(int axis)
      : k(axis), i((axis + 1) % 3), j((axis + 2) % 3), plane(set.add_axis(axis, 0.0)) {}

  // [a0, a1] x [b0, b1] in (i, j), counter-clockwise seen from +e_k.
  PlanePolygon rectangle(double a0, double b0, double a1, double b1) {
    const PlaneRef left{set.add_axis(i, a0), -1}, bottom{set.add_axis(j, b0), -1};
    const PlaneRef right{set.add_axis(i, a1), 1}, top{set.add_axis(j, b1), 1};
    PlanePolygon p{{plane, 1}, {left, bottom, right, top}, {}};
    for (std::size_t m = 0; m < 4; ++m)
      p.vertices.push_back(make_point(set, plane, p.lines[m].id, p.lines[(m + 1) % 4].id));
    return p;
  }
  // A solid's face with the solid on the plane's negative side (below), of primitive `owner`.
  Contribution face_below(double a0, double b0, double a1, double b1, std::size_t owner = 0) {
    return {rectangle(a0, b0, a1, b1), owner, true, false, true};
  }
  Contribution hole_section(double a0, double b0, double a1, double b1, std::size_t owner) {
    return {rectangle(a0, b0, a1, b1), owner, false, true, true};
  }
  // A face below of the rectangle with its corner (a1, b1) cut off by the line through
  // (a1 - d, b1) and (a1, b1 - d): a pentagon. @pre k == 2 (the cut is a vertical plane).
  Contribution corner_cut(double a0, double b0, double a1, double b1, double d, std::size_t owner) {
    PlanePolygon p = rectangle(a0, b0, a1, b1);
    PlaneRecipe cut;
    cut.kind = PlaneRecipe::Kind::through2;  // its right, the corner's side, is outside
    cut.v = {a1, b1 - d, a1 - d, b1};
    const PlaneRef diagonal{set.add(cut), 1};
    p.lines = {p.lines[0], p.lines[1], p.lines[2], diagonal, p.lines[3]};
    p.vertices.clear();
    for (std::size_t m = 0; m < 5; ++m)
      p.vertices.push_back(make_point(set, plane, p.lines[m].id, p.lines[(m + 1) % 5].id));
    return {std::move(p), owner, true, false, true};
  }
};

// Twice the area of a face in the view (i, j), seen from its outside: positive when the face
// is counter-clockwise seen from there (the plane's normal is +e_k).
inline double twice_area_outside(const SolidFace& f, int i, int j) {
  double sum = 0.0;
  for (std::size_t m = 0; m < f.rounded.size(); ++m) {
    const auto& p = f.rounded[m];
    const auto& q = f.rounded[(m + 1) % f.rounded.size()];
    sum += p[std::size_t(i)] * q[std::size_t(j)] - q[std::size_t(i)] * p[std::size_t(j)];
  }
  return sum * f.plane.sign;
}

// Area per (side, owner).
inline std::map<std::pair<int, std::size_t>, double> areas(const std::vector<SolidFace>& faces,
                                                           int i, int j) {
  std::map<std::pair<int, std::size_t>, double> out;
  for (const SolidFace& f : faces)
    out[{f.plane.sign, f.owner}] += twice_area_outside(f, i, j) / 2.0;
  return out;
}

}  // namespace roomcad::detail
