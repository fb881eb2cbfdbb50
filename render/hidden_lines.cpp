// SPDX-License-Identifier: GPL-3.0-or-later
// Hidden-line removal in object space: split feature edges at projected crossings, classify
// each piece by an exact segment-against-faces test towards the viewer.
#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/box.h"
#include "geometry/box_grid.h"
#include "render/camera.h"
#include "render/detail/feature_edges.h"
#include "render/detail/merge_segments.h"
#include "render/line_drawing.h"

namespace roomcad {
namespace {

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
  Box2 box = empty_box2();
  for (int i = 0; i < 3; ++i) {
    Edge3 e{t[i], t[(i + 1) % 3]};
    if (!clip_to_near(pr, e)) continue;
    for (const Point2 p : {pr.project(e.a), pr.project(e.b)}) add_point(box, p.x, p.y);
  }
  return box;
}

/// Everything the per-edge work reads.
struct Scene2 {
  Projector projector;
  std::vector<Edge3> edges;         ///< clipped
  std::vector<Segment2> projected;  ///< one per edge
  std::vector<Triangle3> faces;     ///< occluders (not edge-on)
  BoxGrid edge_grid;                ///< of `projected` (Box2::index: the edge)
  BoxGrid face_grid;                ///< of the faces' picture boxes (Box2::index: the face)
  double far_reach = 1.0;           ///< orthographic: length of the test segment towards the viewer
};

/// @return the box of s grown by `margin` on every side, tagged `index`.
Box2 segment_box(const Segment2& s, std::size_t index = 0, double margin = 0.0) {
  return {std::min(s.a.x, s.b.x) - margin, std::min(s.a.y, s.b.y) - margin,
          std::max(s.a.x, s.b.x) + margin, std::max(s.a.y, s.b.y) + margin, index};
}

/// @return the parameters along s where other feature edges cross or touch its projection.
std::vector<double> split_parameters(const Scene2& sc, std::size_t i) {
  const Segment2& s = sc.projected[i];
  const Point2 d{s.b.x - s.a.x, s.b.y - s.a.y};
  const double len2 = d.x * d.x + d.y * d.y;
  const double tol = 1e-9 * std::sqrt(len2) + 1e-12;
  std::vector<double> ts{0.0, 1.0};
  // The box grown by the tolerance: an end of another edge within it of s splits s.
  const std::vector<std::size_t> near = sc.edge_grid.find(segment_box(s, 0, tol));
  const auto on_s = [&](Point2 p) {  // parameter of p if it lies on s, else -1
    const Point2 ap{p.x - s.a.x, p.y - s.a.y};
    if (std::abs(ap.x * d.y - ap.y * d.x) > tol * std::sqrt(len2)) return -1.0;
    return (ap.x * d.x + ap.y * d.y) / len2;
  };
  for (const std::size_t j : near) {
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
bool is_hidden_at(const Scene2& sc, const Edge3& e, double s, std::vector<std::size_t>& near) {
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
  sc.face_grid.find({p.x, p.y, p.x, p.y, 0}, near);  // faces whose box holds p
  for (const std::size_t f : near) {
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
  std::vector<std::size_t> near;
  double run_start = 0.0;
  int run_hidden = -1;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k, ++out.pieces) {
    const int hidden = is_hidden_at(sc, sc.edges[i], 0.5 * (ts[k] + ts[k + 1]), near) ? 1 : 0;
    if (hidden == run_hidden) continue;
    if (run_hidden >= 0)
      (run_hidden ? out.hidden : out.visible).push_back({at(run_start), at(ts[k])});
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

}  // namespace

HiddenLineResult remove_hidden_lines(const Model& model, const Parts& parts, const LineView& view) {
  Projector pr(view);
  std::vector<Edge3> edges = collect_edges(model, parts);
  std::erase_if(edges, [&](Edge3& e) { return !clip_to_near(pr, e); });
  std::vector<Triangle3> faces = collect_occluders(model, parts, view);
  std::vector<Segment2> projected;
  for (const Edge3& e : edges) projected.push_back({pr.project(e.a), pr.project(e.b)});
  std::vector<Box2> edge_boxes, face_boxes;
  for (std::size_t i = 0; i < projected.size(); ++i)
    edge_boxes.push_back(segment_box(projected[i], i));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Box2 box = occluder_box(pr, faces[f]);
    box.index = f;
    if (!is_empty(box)) face_boxes.push_back(box);
  }
  Scene2 sc{pr,
            std::move(edges),
            std::move(projected),
            std::move(faces),
            BoxGrid(std::move(edge_boxes)),
            BoxGrid(std::move(face_boxes))};
  Box3 extent = empty_box3();
  for (const Edge3& e : sc.edges) {
    add_point(extent, e.a);
    add_point(extent, e.b);
  }
  for (const Triangle3& t : sc.faces)
    for (const glm::dvec3& c : t) add_point(extent, c);
  if (!is_empty(extent))
    sc.far_reach = 2.0 * glm::length(high_corner(extent) - low_corner(extent)) + 1.0;
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
