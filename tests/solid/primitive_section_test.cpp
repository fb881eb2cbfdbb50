// SPDX-License-Identifier: GPL-3.0-or-later
// section_of (detail/primitive_section.h): the section of a convex primitive by a plane crossing
// it, made from its crossing edges, is the polygon that clipping the plane's square by every
// face gives: the same lines in the same cyclic order, at the same exact corners. Planes
// through a vertex (where the crossing edges do not say the section) have no section from
// the crossings, and section_of clips.
#include "solid/detail/general_path/primitive_section.h"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

namespace roomcad::detail {
namespace {

// Whether a and b are one polygon: the same lines and corners, cyclically.
bool same_polygon(const PlaneSet& set, const PlanePolygon& a, const PlanePolygon& b) {
  const std::size_t n = a.lines.size();
  if (n != b.lines.size() || a.vertices.size() != n || b.vertices.size() != n) return false;
  for (std::size_t shift = 0; shift < n; ++shift) {
    bool same = true;
    for (std::size_t m = 0; m < n && same; ++m)
      same = a.lines[m] == b.lines[(m + shift) % n] &&
             is_same_point(set, a.vertices[m], b.vertices[(m + shift) % n]);
    if (same) return true;
  }
  return false;
}

PlaneId add_through(PlaneSet& set, double px, double py, double qx, double qy) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::through2;
  r.v = {px, py, qx, qy};
  return set.add(r);
}

PlaneId add_sloped(PlaneSet& set, double x0, double y0, double x1, double y1, double z,
                   double rise) {
  PlaneRecipe r;
  r.kind = PlaneRecipe::Kind::sloped_top;
  r.v = {x0, y0, x1, y1, z, rise, 0.0};
  return set.add(r);
}

struct Scene {
  PlaneSet set;
  BoxPlanes box = add_box_planes(set, 16.0);
};

// A wall piece: [0, 4] x [0, 0.2] x [0, 2.5] with its top sloped up along x by 0.5 and its
// end at x = 4 mitred.
Primitive sloped_mitred_wall(Scene& s) {
  PlaneSet& set = s.set;
  return *make_convex(
      set, s.box,
      {{set.add_axis(0, 0.0), -1},
       {add_through(set, 4.0, 0.0, 4.2, 0.2), 1},  // the mitre: x - y = 4, right outside
       {set.add_axis(1, 0.0), -1},
       {set.add_axis(1, 0.2), 1},
       {set.add_axis(2, 0.0), -1},
       {add_sloped(set, 0.0, 0.1, 4.0, 0.1, 2.5, 0.5), 1}});
}

TEST(PrimitiveSection, MatchesTheClippedSquareOnAxisObliqueAndSlopedPlanes) {
  Scene s;
  const Primitive wall = sloped_mitred_wall(s);
  ASSERT_EQ(wall.faces.size(), 6u);
  std::vector<PlaneRef> planes;
  for (const double z : {0.3, 1.25, 2.6, 2.9})  // 2.6 and 2.9 cut the sloped top
    planes.push_back({s.set.add_axis(2, z), 1});
  for (const double x : {0.5, 2.0, 3.99, 4.1})  // 4.1 cuts the mitre
    planes.push_back({s.set.add_axis(0, x), -1});
  planes.push_back({s.set.add_axis(1, 0.1), 1});
  planes.push_back({add_through(s.set, 1.0, -1.0, 3.0, 1.0), 1});  // across the wall, askew
  planes.push_back({add_sloped(s.set, 0.0, 0.0, 4.0, 0.2, 1.0, 1.0), -1});
  for (const PlaneRef& h : planes) {
    SCOPED_TRACE(h.id);
    const auto made = section_from_crossings(s.set, wall, h);
    const auto reference = section_by_clipping(s.set, s.box, wall, h);
    ASSERT_TRUE(made && reference);
    EXPECT_TRUE(same_polygon(s.set, *section_of(s.set, s.box, wall, h), *made));
    EXPECT_GE(made->lines.size(), 3u);
    EXPECT_TRUE(same_polygon(s.set, *made, *reference));
    for (const PlaneRef& t : made->lines) {  // every line is a face's, outward
      bool is_face = false;
      for (const PlanePolygon& f : wall.faces) is_face = is_face || f.plane == t;
      EXPECT_TRUE(is_face);
    }
  }
}

TEST(PrimitiveSection, APlaneThroughAVertexOrAnEdgeTakesTheClippingPath) {
  Scene s;
  const Primitive wall = sloped_mitred_wall(s);
  // Through the corner (0, 0, 2.5) of the top, the mitre's edge x - y = 4 at z = 0, and the
  // face y = 0.2 itself (no section: nothing of positive area lies on it inside).
  for (const PlaneRef h : {PlaneRef{s.set.add_axis(2, 2.5), 1},
                           PlaneRef{add_through(s.set, 4.0, 0.0, 4.2, 0.2), -1}}) {
    SCOPED_TRACE(h.id);
    EXPECT_FALSE(section_from_crossings(s.set, wall, h));
    const auto made = section_of(s.set, s.box, wall, h);
    const auto reference = section_by_clipping(s.set, s.box, wall, h);
    ASSERT_EQ(made.has_value(), reference.has_value());
    if (made) {
      EXPECT_TRUE(same_polygon(s.set, *made, *reference));
    }
  }
  EXPECT_FALSE(section_of(s.set, s.box, wall, {s.set.add_axis(2, 5.0), 1}));  // above it all
}

TEST(PrimitiveSection, RandomBoxesCutByRandomPlanesMatchTheClippedSquare) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> at(-3.0, 3.0), size(0.05, 2.0);
  int crossing = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Scene s;
    const double x = at(rng), y = at(rng), z = at(rng), dx = size(rng), dy = size(rng),
                 dz = size(rng);
    const Primitive box =
        *make_convex(s.set, s.box,
                     {{s.set.add_axis(0, x), -1},
                      {s.set.add_axis(0, x + dx), 1},
                      {s.set.add_axis(1, y), -1},
                      {s.set.add_axis(1, y + dy), 1},
                      {s.set.add_axis(2, z), -1},
                      {add_sloped(s.set, x, y, x + dx, y + dy, z + dz, dz * at(rng) / 6.0), 1}});
    const PlaneRef h =
        trial % 3 == 0 ? PlaneRef{s.set.add_axis(trial % 2, x + dx * size(rng) / 2.0), 1}
        : trial % 3 == 1
            ? PlaneRef{add_through(s.set, at(rng), at(rng), at(rng), at(rng)), 1}
            : PlaneRef{add_sloped(s.set, x, y, at(rng), at(rng), z + dz / 2, at(rng)), -1};
    const auto made = section_of(s.set, s.box, box, h);
    const auto reference = section_by_clipping(s.set, s.box, box, h);
    ASSERT_EQ(made.has_value(), reference.has_value()) << trial;
    if (!made) continue;
    EXPECT_TRUE(same_polygon(s.set, *made, *reference)) << trial;
    if (const auto from_crossings = section_from_crossings(s.set, box, h)) {
      ++crossing;
      EXPECT_TRUE(same_polygon(s.set, *from_crossings, *reference)) << trial;
    }
  }
  EXPECT_GT(crossing, 60);  // the test says something: many sections come from the crossings
}

}  // namespace
}  // namespace roomcad::detail
