// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/detail/ifc_shapes.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace roomcad::io_detail {
namespace {

std::string reals(std::initializer_list<double> values) {
  std::string out = "(";
  for (const double v : values) {
    if (out.size() > 1) out += ',';
    step::append_real(out, v);
  }
  return out + ')';
}

std::string refs(const std::vector<int>& ids) {
  std::string out = "(";
  for (const int id : ids) {
    if (out.size() > 1) out += ',';
    out += step::ref(id);  // appended, not `"," + ...`: GCC 12 warns (-Wrestrict) on that
  }
  return out + ')';
}

Point2 minus(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }

/// @return the point where the line p + s d meets the line q + t e, if they are not parallel.
std::optional<Point2> meet(Point2 p, Point2 d, Point2 q, Point2 e) {
  const double den = cross(d, e);
  if (den == 0.0) return std::nullopt;
  const double s = cross(minus(q, p), e) / den;
  return Point2{p.x + s * d.x, p.y + s * d.y};
}

/// @return the distance from p to the segment [a, b].
double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const Point2 d = minus(b, a);
  const double len2 = d.x * d.x + d.y * d.y;
  const double t =
      len2 > 0.0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * d.x, p.y - a.y - t * d.y);
}

/// The wall that the end `e` of wall `w` stops on as a T, if it is exactly one.
std::optional<std::size_t> t_host(const JoinedWalls& walls, std::size_t w, WallEnd e) {
  const Plan& plan = walls.plan;
  const Wall& wall = plan.walls[w];
  const Point2 end = e == WallEnd::from ? wall.from : wall.to;
  const double tol = plan.site.tolerance;
  std::optional<std::size_t> host;
  int meetings = 0;
  for (const std::size_t j : walls.joins_of[w]) {
    const Join& join = walls.joins.pairs[j];
    const std::size_t other = join.a == w ? join.b : join.a;
    const Wall& o = plan.walls[other];
    if (distance_to_segment(end, o.from, o.to) > tol) continue;
    ++meetings;
    const bool at_other_end = std::hypot(end.x - o.from.x, end.y - o.from.y) <= tol ||
                              std::hypot(end.x - o.to.x, end.y - o.to.y) <= tol;
    if (join.kind == JoinKind::unite && !at_other_end) host = other;
  }
  return meetings == 1 ? host : std::nullopt;
}

}  // namespace

int IfcShapeWriter::point(Point2 p) { return out.add("IFCCARTESIANPOINT", reals({p.x, p.y})); }

int IfcShapeWriter::point(Point2 p, double z) {
  return out.add("IFCCARTESIANPOINT", reals({p.x, p.y, z}));
}

int IfcShapeWriter::placement(Point2 at, double z, std::array<double, 3> axis,
                              std::array<double, 3> x_axis) {
  const int location = point(at, z);
  const int a = out.add("IFCDIRECTION", reals({axis[0], axis[1], axis[2]}));
  const int x = out.add("IFCDIRECTION", reals({x_axis[0], x_axis[1], x_axis[2]}));
  return out.add("IFCAXIS2PLACEMENT3D",
                 step::ref(location) + ',' + step::ref(a) + ',' + step::ref(x));
}

int IfcShapeWriter::closed_polyline(const std::vector<Point2>& ring) {
  std::vector<int> points;
  points.reserve(ring.size() + 1);
  for (const Point2& p : ring) points.push_back(point(p));
  points.push_back(points.front());
  return out.add("IFCPOLYLINE", refs(points));
}

int IfcShapeWriter::extrusion(const std::vector<Point2>& outline,
                              const std::vector<std::vector<Point2>>& holes, int position,
                              double depth, Color color) {
  const int outer = closed_polyline(outline);
  int profile = 0;
  if (holes.empty()) {
    profile = out.add("IFCARBITRARYCLOSEDPROFILEDEF", ".AREA.,$," + step::ref(outer));
  } else {
    std::vector<int> inner;
    for (const auto& hole : holes) inner.push_back(closed_polyline(hole));
    profile = out.add("IFCARBITRARYPROFILEDEFWITHVOIDS",
                      ".AREA.,$," + step::ref(outer) + ',' + refs(inner));
  }
  std::string parameters =
      step::ref(profile) + ',' + (position ? step::ref(position) : "$") + ',' + step::ref(up) + ',';
  step::append_real(parameters, depth);
  const int solid = out.add("IFCEXTRUDEDAREASOLID", parameters);
  style(solid, color);
  return solid;
}

int IfcShapeWriter::face_set(const std::vector<std::array<double, 3>>& points,
                             const std::vector<std::array<int, 3>>& triangles, Color color) {
  std::string list = "((";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) list += "),(";
    for (int k = 0; k < 3; ++k) {
      if (k) list += ',';
      step::append_real(list, points[i][static_cast<std::size_t>(k)]);
    }
  }
  const int coordinates = out.add("IFCCARTESIANPOINTLIST3D", list + "))");
  std::string indices = "(";
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    indices += i ? ",(" : "(";
    indices += std::to_string(t[0] + 1) + ',' + std::to_string(t[1] + 1) + ',' +
               std::to_string(t[2] + 1) + ')';
  }
  const int set =
      out.add("IFCTRIANGULATEDFACESET", step::ref(coordinates) + ",$,.T.," + indices + "),$");
  style(set, color);
  return set;
}

int IfcShapeWriter::product_shape(const std::string& type, const std::vector<int>& items,
                                  int axis) {
  std::vector<int> representations;
  if (axis >= 0) {
    representations.push_back(
        out.add("IFCSHAPEREPRESENTATION",
                step::ref(axis_context) + ",'Axis','Curve2D',(" + step::ref(axis) + ')'));
  }
  representations.push_back(out.add(
      "IFCSHAPEREPRESENTATION", step::ref(body_context) + ",'Body','" + type + "'," + refs(items)));
  return out.add("IFCPRODUCTDEFINITIONSHAPE", "$,$," + refs(representations));
}

int IfcShapeWriter::style_of(Color c) {
  const std::uint32_t key = (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
  if (const auto it = styles.find(key); it != styles.end()) return it->second;
  std::string rgb = "$";
  for (const std::uint8_t channel : {c.r, c.g, c.b}) {
    rgb += ',';
    step::append_real(rgb, channel / 255.0);
  }
  const int colour = out.add("IFCCOLOURRGB", rgb);
  const int shading = out.add("IFCSURFACESTYLESHADING", step::ref(colour) + ",0.");
  std::string name;
  step::append_string(name, to_string(c));
  const int style = out.add("IFCSURFACESTYLE", name + ",.BOTH.,(" + step::ref(shading) + ')');
  styles.emplace(key, style);
  return style;
}

void IfcShapeWriter::style(int item, Color color) {
  out.add("IFCSTYLEDITEM", step::ref(item) + ",(" + step::ref(style_of(color)) + "),$");
}

JoinedWalls::JoinedWalls(const Plan& plan, const Joins& joins)
    : plan(plan), joins(joins), joins_of(plan.walls.size()) {
  for (std::size_t j = 0; j < joins.pairs.size(); ++j) {
    joins_of[joins.pairs[j].a].push_back(j);
    joins_of[joins.pairs[j].b].push_back(j);
  }
}

std::array<Point2, 4> export_footprint(const JoinedWalls& walls, std::size_t w) {
  const Plan& plan = walls.plan;
  std::array<Point2, 4> f = wall_footprint(plan, walls.joins, w);
  const Wall& wall = plan.walls[w];
  for (const WallEnd e : {WallEnd::from, WallEnd::to}) {
    const std::optional<std::size_t> host = t_host(walls, w, e);
    if (!host) continue;
    const Wall& h = plan.walls[*host];
    const Point2 hd = minus(h.to, h.from);
    const double hl = std::hypot(hd.x, hd.y);
    const Point2 far_end = e == WallEnd::from ? wall.to : wall.from;
    // The face of the host on the side where this wall's far end lies.
    const double side = cross(hd, minus(far_end, h.from)) > 0.0 ? 1.0 : -1.0;
    const Point2 face{h.from.x - side * hd.y / hl * h.thickness / 2,
                      h.from.y + side * hd.x / hl * h.thickness / 2};
    const Point2 d = minus(wall.to, wall.from);
    // Corners of this end: from-right (0), from-left (3); to-right (1), to-left (2).
    for (const std::size_t k :
         e == WallEnd::from ? std::array<std::size_t, 2>{0, 3} : std::array<std::size_t, 2>{1, 2}) {
      if (const auto p = meet(f[k], d, face, hd)) f[k] = *p;
    }
  }
  return f;
}

int wall_axis(IfcShapeWriter& shapes, const std::vector<Point2>& line) {
  std::vector<int> points;
  points.reserve(line.size());
  for (const Point2& p : line) points.push_back(shapes.point(p));
  return shapes.out.add("IFCPOLYLINE", refs(points));
}

int wall_body(IfcShapeWriter& shapes, const Wall& wall, const std::array<Point2, 4>& footprint) {
  const std::vector<Point2> ring(footprint.begin(), footprint.end());
  const double end_height = wall.height_at_end.value_or(wall.height);
  if (end_height == wall.height) return shapes.extrusion(ring, {}, 0, wall.height, wall.color);
  // A sloped top: the plane through the top edge, height + (end - height) u / length at u
  // metres along from -> to (docs/plan-format.md, version 2).
  const Point2 d = minus(wall.to, wall.from);
  const double length = std::hypot(d.x, d.y);
  std::vector<std::array<double, 3>> points;
  for (const Point2& p : footprint) points.push_back({p.x, p.y, 0.0});
  for (const Point2& p : footprint) {
    const double u = ((p.x - wall.from.x) * d.x + (p.y - wall.from.y) * d.y) / length;
    points.push_back({p.x, p.y, wall.height + (end_height - wall.height) * u / length});
  }
  // Bottom 0..3 (seen from below: clockwise from above), top 4..7, four sides.
  std::vector<std::array<int, 3>> triangles{{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}};
  for (int k = 0; k < 4; ++k) {
    const int n = (k + 1) % 4;
    triangles.push_back({k, n, n + 4});
    triangles.push_back({k, n + 4, k + 4});
  }
  return shapes.face_set(points, triangles, wall.color);
}

int chord_piece_void(IfcShapeWriter& shapes, const Wall& chord,
                     const std::array<Point2, 4>& footprint, const Opening& piece,
                     std::array<bool, 2> mitred) {
  const Point2 d = minus(chord.to, chord.from);
  const double length = std::hypot(d.x, d.y);
  const Point2 along{d.x / length, d.y / length}, left{-along.y, along.x};
  // Per end, its right and its left point, a thickness from the centre line (twice the
  // half-thickness the footprint reaches: through both faces with room to spare).
  auto square = [&](double u) {
    const Point2 c{chord.from.x + along.x * u, chord.from.y + along.y * u};
    const double t = chord.thickness;
    return std::array<Point2, 2>{Point2{c.x - left.x * t, c.y - left.y * t},
                                 Point2{c.x + left.x * t, c.y + left.y * t}};
  };
  auto on_mitre = [&](Point2 right, Point2 left_corner) {
    const Point2 half{(left_corner.x - right.x) / 2, (left_corner.y - right.y) / 2};
    return std::array<Point2, 2>{Point2{right.x - half.x, right.y - half.y},
                                 Point2{left_corner.x + half.x, left_corner.y + half.y}};
  };
  // Footprint corners: from-right 0, to-right 1, to-left 2, from-left 3.
  const auto start = mitred[0] ? on_mitre(footprint[0], footprint[3]) : square(piece.offset);
  const auto end =
      mitred[1] ? on_mitre(footprint[1], footprint[2]) : square(piece.offset + piece.width);
  const int position = shapes.placement({0.0, 0.0}, piece.sill, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0});
  return shapes.extrusion({start[0], end[0], end[1], start[1]}, {}, position, piece.height,
                          chord.color);
}

}  // namespace roomcad::io_detail
