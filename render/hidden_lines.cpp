// SPDX-License-Identifier: GPL-3.0-or-later
// Hidden-line removal in object space: split feature edges at projected crossings, classify
// each piece by an exact segment-against-faces test towards the viewer.
#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "render/camera.h"
#include "render/detail/box_grid.h"
#include "render/detail/feature_edges.h"
#include "render/detail/merge_segments.h"
#include "render/line_drawing.h"

namespace roomcad {
namespace {

using detail::Box2;
using detail::Edge3;
using detail::Triangle3;

/// An occluder is not trusted closer than this in front of an edge (metres): the edge's own
/// faces pass through it.
constexpr double kOcclusionOffset = 1e-7;

/// World -> picture plane, and the depth along the view.
struct Projector {
  bool perspective = false;
  glm::dvec3 eye{0.0}, forward{0.0}, right{0.0}, up{0.0};

  explicit Projector(const LineView& v) : perspective(v.perspective), eye(v.eye) {
    forward = glm::normalize(v.forward);
    right = glm::normalize(glm::cross(forward, v.up));
    up = glm::cross(right, forward);
  }
  [[nodiscard]] double depth(const glm::dvec3& p) const { return glm::dot(p - eye, forward); }
  [[nodiscard]] Point2 project(const glm::dvec3& p) const {
    const glm::dvec3 d = p - eye;
    const double x = glm::dot(d, right), y = glm::dot(d, up);
    if (!perspective) return {x, y};
    const double z = glm::dot(d, forward);
    return {x / z, y / z};
  }
};

/// Clips an edge to the half-space in front of the near plane. @return false if nothing is left.
bool clip_to_near(const Projector& pr, Edge3& e) {
  if (!pr.perspective) return true;
  const double da = pr.depth(e.a) - kPerspectiveNear, db = pr.depth(e.b) - kPerspectiveNear;
  if (da < 0.0 && db < 0.0) return false;
  if (da < 0.0) e.a = e.a + (e.b - e.a) * (da / (da - db));
  if (db < 0.0) e.b = e.b + (e.a - e.b) * (db / (db - da));
  return true;
}

/// The picture-plane box of a triangle's part in front of the near plane (empty if none).
Box2 occluder_box(const Projector& pr, const Triangle3& t) {
  Box2 box;
  for (int i = 0; i < 3; ++i) {
    Edge3 e{t[i], t[(i + 1) % 3]};
    if (!clip_to_near(pr, e)) continue;
    box.add(pr.project(e.a));
    box.add(pr.project(e.b));
  }
  return box;
}

/// Everything the per-edge work reads.
struct Scene2 {
  Projector projector;
  std::vector<Edge3> edges;         ///< clipped
  std::vector<Segment2> projected;  ///< one per edge
  std::vector<Triangle3> faces;     ///< occluders (not edge-on)
  std::vector<Box2> face_boxes;
  detail::BoxGrid edge_grid;
  detail::BoxGrid face_grid;
  double far_reach = 1.0;  ///< orthographic: length of the test segment towards the viewer
};

Box2 segment_box(const Segment2& s) {
  Box2 b;
  b.add(s.a);
  b.add(s.b);
  return b;
}

/// @return the parameters along s where other feature edges cross or touch its projection.
std::vector<double> split_parameters(const Scene2& sc, std::size_t i) {
  const Segment2& s = sc.projected[i];
  const Point2 d{s.b.x - s.a.x, s.b.y - s.a.y};
  const double len2 = d.x * d.x + d.y * d.y;
  const double tol = 1e-9 * std::sqrt(len2) + 1e-12;
  std::vector<double> ts{0.0, 1.0};
  std::vector<std::uint32_t> near;
  sc.edge_grid.query(segment_box(s), near);
  const auto on_s = [&](Point2 p) {  // parameter of p if it lies on s, else -1
    const Point2 ap{p.x - s.a.x, p.y - s.a.y};
    if (std::abs(ap.x * d.y - ap.y * d.x) > tol * std::sqrt(len2)) return -1.0;
    return (ap.x * d.x + ap.y * d.y) / len2;
  };
  for (const std::uint32_t j : near) {
    if (j == i) continue;
    const Segment2& o = sc.projected[j];
    const Point2 e{o.b.x - o.a.x, o.b.y - o.a.y};
    const double den = d.x * e.y - d.y * e.x;
    const Point2 ao{o.a.x - s.a.x, o.a.y - s.a.y};
    if (std::abs(den) > 1e-12 * std::sqrt(len2 * (e.x * e.x + e.y * e.y))) {
      const double t = (ao.x * e.y - ao.y * e.x) / den, u = (ao.x * d.y - ao.y * d.x) / den;
      if (u >= 0.0 && u <= 1.0) ts.push_back(t);
    }
    ts.push_back(on_s(o.a));
    ts.push_back(on_s(o.b));
  }
  std::erase_if(ts, [](double t) { return !(t > 0.0 && t < 1.0); });
  ts.push_back(0.0);
  ts.push_back(1.0);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end(), [](double a, double b) { return b - a < 1e-9; }),
           ts.end());
  ts.back() = 1.0;
  return ts;
}

/// @return whether the point of edge `e` at picture parameter s is hidden by some face.
bool is_hidden_at(const Scene2& sc, const Edge3& e, double s, std::vector<std::uint32_t>& near) {
  const Projector& pr = sc.projector;
  double t = s;
  if (pr.perspective) {  // picture parameter -> edge parameter (1 / depth is linear)
    const double za = pr.depth(e.a), zb = pr.depth(e.b);
    t = s * za / ((1.0 - s) * zb + s * za);
  }
  const glm::dvec3 m = e.a + (e.b - e.a) * t;
  const glm::dvec3 target = pr.perspective ? pr.eye : m - pr.forward * sc.far_reach;
  const glm::dvec3 start = m + glm::normalize(target - m) * kOcclusionOffset;
  const Point2 p = pr.project(m);
  Box2 at;
  at.add(p);
  sc.face_grid.query(at, near);
  for (const std::uint32_t f : near) {
    const Box2& b = sc.face_boxes[f];
    if (p.x < b.min.x || p.x > b.max.x || p.y < b.min.y || p.y > b.max.y) continue;
    if (detail::segment_meets_triangle(start, target, sc.faces[f])) return true;
  }
  return false;
}

struct EdgeLines {
  std::vector<Segment2> visible, hidden;
  std::size_t pieces = 0;
};

EdgeLines classify_edge(const Scene2& sc, std::size_t i) {
  const std::vector<double> ts = split_parameters(sc, i);
  const Segment2& s = sc.projected[i];
  const auto at = [&](double t) {
    return Point2{s.a.x + (s.b.x - s.a.x) * t, s.a.y + (s.b.y - s.a.y) * t};
  };
  EdgeLines out;
  std::vector<std::uint32_t> near;
  double run_start = 0.0;
  int run_hidden = -1;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k, ++out.pieces) {
    const int hidden = is_hidden_at(sc, sc.edges[i], 0.5 * (ts[k] + ts[k + 1]), near) ? 1 : 0;
    if (hidden == run_hidden) continue;
    if (run_hidden >= 0) (run_hidden ? out.hidden : out.visible).push_back({at(run_start), at(ts[k])});
    run_start = ts[k];
    run_hidden = hidden;
  }
  if (run_hidden >= 0) (run_hidden ? out.hidden : out.visible).push_back({at(run_start), at(1.0)});
  return out;
}

std::vector<Edge3> collect_edges(const Model& model, const Parts& parts) {
  std::vector<Edge3> edges;
  if (parts.walls) detail::append_feature_edges(model.walls, edges);
  if (parts.floor) detail::append_feature_edges(model.floor, edges);
  if (parts.fixtures) detail::append_feature_edges(model.fixtures, edges);
  return edges;
}

std::vector<Triangle3> collect_occluders(const Model& model, const Parts& parts,
                                         const LineView& view) {
  std::vector<Triangle3> faces;
  if (parts.walls) detail::append_triangles(model.walls, faces);
  if (parts.floor) detail::append_triangles(model.floor, faces);
  if (parts.fixtures) detail::append_triangles(model.fixtures, faces);
  std::erase_if(faces, [&](const Triangle3& t) {
    return detail::is_edge_on(t, view.eye, view.forward, view.perspective);
  });
  return faces;
}

Box2 picture_bounds(const Scene2& sc) {
  Box2 all;
  for (const Segment2& s : sc.projected) all = detail::merge_boxes(all, segment_box(s));
  for (const Box2& b : sc.face_boxes) all = detail::merge_boxes(all, b);
  if (all.is_empty()) all.add({0.0, 0.0});
  return all;
}

}  // namespace

HiddenLineResult remove_hidden_lines(const Model& model, const Parts& parts, const LineView& view) {
  Projector pr(view);
  std::vector<Edge3> edges = collect_edges(model, parts);
  std::erase_if(edges, [&](Edge3& e) { return !clip_to_near(pr, e); });
  std::vector<Triangle3> faces = collect_occluders(model, parts, view);
  std::vector<Box2> boxes;
  for (const Triangle3& t : faces) boxes.push_back(occluder_box(pr, t));
  std::vector<Segment2> projected;
  for (const Edge3& e : edges) projected.push_back({pr.project(e.a), pr.project(e.b)});
  Scene2 sc{pr, std::move(edges), std::move(projected), std::move(faces), std::move(boxes),
            detail::BoxGrid({}, 1), detail::BoxGrid({}, 1)};
  const Box2 bounds = picture_bounds(sc);
  sc.edge_grid = detail::BoxGrid(bounds, sc.edges.size());
  sc.face_grid = detail::BoxGrid(bounds, sc.faces.size());
  Bounds extent;
  for (std::uint32_t i = 0; i < sc.edges.size(); ++i) {
    sc.edge_grid.insert(segment_box(sc.projected[i]), i);
    extent.add(sc.edges[i].a);
    extent.add(sc.edges[i].b);
  }
  for (std::uint32_t f = 0; f < sc.faces.size(); ++f) {
    if (!sc.face_boxes[f].is_empty()) sc.face_grid.insert(sc.face_boxes[f], f);
    for (const glm::dvec3& c : sc.faces[f]) extent.add(c);
  }
  if (!extent.is_empty()) sc.far_reach = 2.0 * glm::length(extent.max - extent.min) + 1.0;
  std::vector<EdgeLines> per_edge(sc.edges.size());
  tbb::parallel_for(std::size_t{0}, sc.edges.size(),
                    [&](std::size_t i) { per_edge[i] = classify_edge(sc, i); });
  HiddenLineResult out;
  out.feature_edges = sc.edges.size();
  for (EdgeLines& e : per_edge) {
    out.pieces += e.pieces;
    out.visible.insert(out.visible.end(), e.visible.begin(), e.visible.end());
    out.hidden.insert(out.hidden.end(), e.hidden.begin(), e.hidden.end());
  }
  out.visible = detail::merge_collinear(std::move(out.visible));
  out.hidden = detail::merge_collinear(std::move(out.hidden));
  return out;
}

}  // namespace roomcad
