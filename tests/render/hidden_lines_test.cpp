// SPDX-License-Identifier: GPL-3.0-or-later
// Hidden-line removal: pieces classified as a sampled ray cast says, creases only, views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/detail/feature_edges.h"
#include "render/line_drawing.h"
#include "scene_support.h"
#include "solid/build_model.h"

namespace roomcad::test {
namespace {

/// Distance from p to the segment s.
double distance_to(Point2 p, const Segment2& s) {
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const double len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0.0 ? std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - s.a.x - t * dx, p.y - s.a.y - t * dy);
}

bool is_on_any(Point2 p, const std::vector<Segment2>& segments, double tol) {
  return std::any_of(segments.begin(), segments.end(),
                     [&](const Segment2& s) { return distance_to(p, s) <= tol; });
}

/// A 4 m wall with a 1.2 x 1.0 m window (sill 1.0 m) and, 1.5 m behind it, a 2 x 0.6 x 1.8 m
/// box: looking north, the box shows only through the window.
Model wall_window_and_box() {
  Model m;
  add_face_properties(m.walls);
  const auto quad = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
    add_face(m.walls, {a, b, c, d}, 0, FaceKind::wall_face, kWallColor);
  };
  // The wall's south face as four quads around the window (x 1.4..2.6, z 1.0..2.0), y = 0.
  quad({0, 0, 0}, {4, 0, 0}, {4, 0, 1}, {0, 0, 1});
  quad({0, 0, 2}, {4, 0, 2}, {4, 0, 2.5}, {0, 0, 2.5});
  quad({0, 0, 1}, {1.4, 0, 1}, {1.4, 0, 2}, {0, 0, 2});
  quad({2.6, 0, 1}, {4, 0, 1}, {4, 0, 2}, {2.6, 0, 2});
  add_box(m.walls, {1.0, 1.5, 0.0}, {3.0, 2.1, 1.8}, 1);
  return m;
}

/// The reference: is the point seen from the south (no face in front of it)?
bool is_seen_from_south(const RayCaster& rays, const glm::dvec3& p) {
  return !rays.is_blocked(p + glm::dvec3(0, -1e-6, 0), {0, -1, 0});
}

TEST(HiddenLines, PiecesAreExactlyTheOccludedOnes) {
  const Model model = wall_window_and_box();
  const LineView south = *preset_line_view("south");
  const HiddenLineResult r = remove_hidden_lines(model, Parts{}, south);
  ASSERT_FALSE(r.visible.empty());
  ASSERT_FALSE(r.hidden.empty());
  std::vector<detail::Edge3> edges;
  detail::append_feature_edges(model.walls, edges);
  const RayCaster rays({&model.walls});
  int checked_visible = 0, checked_hidden = 0;
  for (const detail::Edge3& e : edges) {
    for (int k = 1; k < 64; ++k) {
      const glm::dvec3 p = e.a + (e.b - e.a) * (k / 64.0);
      const Point2 q{p.x, p.z};  // south view: x right, z up
      // Within 1 mm of a window edge the verdict changes: not a fair sample.
      const bool near_window_edge = std::abs(p.x - 1.4) < 1e-3 || std::abs(p.x - 2.6) < 1e-3 ||
                                    std::abs(p.z - 1.0) < 1e-3 || std::abs(p.z - 2.0) < 1e-3;
      if (near_window_edge || p.y == 0.0) continue;  // the wall's own edges are checked below
      if (is_seen_from_south(rays, p)) {
        EXPECT_TRUE(is_on_any(q, r.visible, 1e-9)) << p.x << " " << p.y << " " << p.z;
        ++checked_visible;
      } else {
        // (A hidden back edge may project onto a visible front edge: only on-hidden is owed.)
        EXPECT_TRUE(is_on_any(q, r.hidden, 1e-9)) << p.x << " " << p.y << " " << p.z;
        ++checked_hidden;
      }
    }
  }
  EXPECT_GT(checked_visible, 20);
  EXPECT_GT(checked_hidden, 100);
  // The window's outline and the wall's outline are visible; the box's top edge at z = 1.8 is
  // seen exactly where the window is (x 1.4 .. 2.6) and hidden elsewhere.
  EXPECT_TRUE(is_on_any({2.0, 1.8}, r.visible, 1e-9));
  EXPECT_TRUE(is_on_any({1.2, 1.8}, r.hidden, 1e-9));
  EXPECT_FALSE(is_on_any({1.2, 1.8}, r.visible, 1e-9));
  EXPECT_FALSE(is_on_any({1.0, 0.5}, r.visible, 1e-9));  // the box's side edge, behind the wall
  EXPECT_TRUE(is_on_any({2.8, 1.8}, r.hidden, 1e-9));
  EXPECT_TRUE(is_on_any({2.0, 2.0}, r.visible, 1e-9));
}

TEST(HiddenLines, NoEdgeBetweenCoplanarFaces) {
  // A 2 x 1 floor of two coplanar tiles sharing an edge, and a fold along the same edge.
  SolidMesh mesh;
  std::vector<SolidMesh::VertexHandle> v;
  for (const auto& p :
       {OpenMesh::Vec3d(0, 0, 0), OpenMesh::Vec3d(1, 0, 0), OpenMesh::Vec3d(1, 1, 0),
        OpenMesh::Vec3d(0, 1, 0), OpenMesh::Vec3d(2, 0, 0), OpenMesh::Vec3d(2, 1, 0),
        OpenMesh::Vec3d(2, 0, 0.5), OpenMesh::Vec3d(2, 1, 0.5)})
    v.push_back(mesh.add_vertex(p));
  mesh.add_face(v[0], v[1], v[2], v[3]);
  const auto second = mesh.add_face(v[1], v[4], v[5], v[2]);
  std::vector<detail::Edge3> edges;
  detail::append_feature_edges(mesh, edges);
  EXPECT_EQ(edges.size(), 6u);  // the outline only
  for (const detail::Edge3& e : edges) EXPECT_FALSE(e.a.x == 1.0 && e.b.x == 1.0);
  mesh.delete_face(second, false);
  mesh.garbage_collection();
  mesh.add_face(v[1], v[6], v[7], v[2]);  // now the second tile rises: x = 1 is a crease
  edges.clear();
  detail::append_feature_edges(mesh, edges);
  EXPECT_EQ(edges.size(), 7u);
  // A non-convex face wrapped round a square one in its notch: the farthest corner of the
  // first from their shared edge (y = 1) lies on the second's side; still one plane, no crease.
  SolidMesh notch;
  std::vector<SolidMesh::VertexHandle> n;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {0, 0}, {3, 0}, {3, 5}, {2, 5}, {2, 1}, {1, 1}, {1, 5}, {0, 5}})
    n.push_back(notch.add_vertex({x, y, 0.0}));
  notch.add_face(n);
  notch.add_face(std::vector{n[5], n[4], n[3], n[6]});
  edges.clear();
  detail::append_feature_edges(notch, edges);
  EXPECT_EQ(edges.size(), 6u);  // the 3 x 5 outline (its top in three pieces)
  Model model;
  add_face_properties(model.walls);
  add_box(model.walls, {0, 0, 0}, {1, 1, 1}, 0);
  // Seen from the iso direction a cube shows 9 edges and hides 3; merged, no diagonals.
  const HiddenLineResult r = remove_hidden_lines(model, Parts{}, *preset_line_view("iso"));
  EXPECT_EQ(r.visible.size(), 9u);
  EXPECT_EQ(r.hidden.size(), 3u);
}

/// One 4 m wall with a window, turned `degrees` about the origin.
Plan turned_wall(double degrees) {
  const double a = degrees * M_PI / 180.0;
  Plan plan;
  plan.site.origin = {-6.0, -6.0};
  plan.site.cells = {12, 12};
  Wall& w = plan.walls.emplace_back();
  w.id = "w";
  w.from = {0.0, 0.0};
  w.to = {4.0 * std::cos(a), 4.0 * std::sin(a)};
  Opening& o = plan.openings.emplace_back();
  o.id = "win";
  o.type = OpeningType::window;
  o.wall = "w";
  o.offset = 1.4;
  o.width = 1.2;
  return plan;
}

TEST(HiddenLines, RoundingOfTurnedWallsMakesNoCreases) {
  // Turned, the faces around the window are one plane only up to the doubles' rounding; they
  // must still draw no edge between them: feature edges as long in all as the axis-aligned
  // wall's (their count may differ: the modeller may split an edge at another vertex).
  const auto total_length = [](const Plan& plan) {
    std::vector<detail::Edge3> edges;
    detail::append_feature_edges(build_model(plan).walls, edges);
    double sum = 0.0;
    for (const detail::Edge3& e : edges) sum += glm::length(e.b - e.a);
    return sum;
  };
  const double straight = total_length(turned_wall(0.0));
  EXPECT_GT(straight, 0.0);
  EXPECT_NEAR(total_length(turned_wall(31.0)), straight, 1e-9);
}

TEST(HiddenLines, CollinearPiecesAreMerged) {
  Model model;
  add_face_properties(model.walls);
  // Two boxes side by side sharing a face: the top front edge is one line of 2 m.
  add_box(model.walls, {0, 0, 0}, {1, 1, 1}, 0);
  add_box(model.walls, {1, 0, 0}, {2, 1, 1}, 1);
  const HiddenLineResult r = remove_hidden_lines(model, Parts{}, *preset_line_view("south"));
  const auto is_top = [](const Segment2& s) { return s.a.y == 1.0 && s.b.y == 1.0; };
  ASSERT_EQ(std::count_if(r.visible.begin(), r.visible.end(), is_top), 1);
  const auto top = *std::find_if(r.visible.begin(), r.visible.end(), is_top);
  EXPECT_DOUBLE_EQ(std::abs(top.b.x - top.a.x), 2.0);
}

TEST(HiddenLines, PerspectiveCameraClipsAtTheEye) {
  const Model model = wall_window_and_box();
  // Standing between the wall and the box, looking at the box: the wall behind is not drawn
  // and nothing behind the eye makes a line.
  Camera cam = look_from({2.0, 0.8, 1.2}, {2.0, 3.0, 1.0}, 60.0);
  const HiddenLineResult r = remove_hidden_lines(model, Parts{}, camera_line_view(cam));
  ASSERT_FALSE(r.visible.empty());
  for (const auto* lines : {&r.visible, &r.hidden})
    for (const Segment2& s : *lines) {
      EXPECT_TRUE(std::isfinite(s.a.x) && std::isfinite(s.b.y));
    }
  const LineDrawing d = draw_line_view(model, camera_line_view(cam), {}, "test");
  EXPECT_EQ(d.frame.size(), 4u);
  for (const PaperLine& l : d.visible) {
    for (const Point2 p : {l.a, l.b}) {
      EXPECT_GE(p.x, 10.0 - 1e-9);
      EXPECT_LE(p.x, 280.0 + 1e-9);
    }
  }
}

TEST(HiddenLines, ElevationsAreOrthographicToScale) {
  const Model model = wall_window_and_box();
  const LineDrawing d = draw_line_view(model, *preset_line_view("south"), {.scale = 20.0}, "t");
  // 4 m wide at 1:20 is 200 mm, plus 10 mm margins.
  EXPECT_NEAR(d.width, 220.0, 1e-9);
  EXPECT_FALSE(d.scale_bar_black.empty());
  const LineDrawing off = draw_line_view(model, *preset_line_view("south"),
                                         {.scale = 20.0, .hidden = HiddenLines::off}, "t");
  EXPECT_TRUE(off.hidden.empty());
  EXPECT_EQ(off.visible.size(), d.visible.size());
}

}  // namespace
}  // namespace roomcad::test
