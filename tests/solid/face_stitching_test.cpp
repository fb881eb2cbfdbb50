// SPDX-License-Identifier: GPL-3.0-or-later
// stitch_faces (detail/face_stitching.h): a vertex of one face lying inside an edge of another
// is inserted into that edge, in order along it, and only there: on edges along an axis (their
// line's points, found by lookup) and on slanted ones (the grid's walk). Faces on z = 0.
#include "solid/detail/general_path/face_stitching.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "tests/solid/axis_plane.h"

namespace roomcad::detail {
namespace {

// A face with corners `vertices` and lines[k] the line of the edge from corner k to k + 1.
SolidFace face_of(const PlaneSet& set, PlaneRef plane, std::vector<XPoint> vertices,
                  std::vector<PlaneRef> lines) {
  SolidFace f{plane, 0, std::move(vertices), std::move(lines), {}};
  for (const XPoint& v : f.vertices) f.rounded.push_back(round_point(set, v));
  return f;
}

// A convex polygon's face (a polygon's vertex k is where its lines k and k + 1 meet).
SolidFace face_of(const PlaneSet& set, const PlanePolygon& polygon) {
  std::vector<PlaneRef> lines(polygon.lines.begin() + 1, polygon.lines.end());
  lines.push_back(polygon.lines.front());
  return face_of(set, polygon.plane, polygon.vertices, std::move(lines));
}

// The plan coordinates (x, y) of the stitched polygon of face k.
std::vector<std::array<double, 2>> corners(const IndexedSoup& soup, std::size_t k) {
  std::vector<std::array<double, 2>> out;
  for (const std::size_t i : soup.polygons[k])
    out.push_back({soup.points[i][0], soup.points[i][1]});
  return out;
}

using Corners = std::vector<std::array<double, 2>>;

IndexedSoup stitch(const PlaneSet& set, const std::vector<SolidFace>& faces) {
  std::vector<const SolidFace*> pointers;
  for (const SolidFace& f : faces) pointers.push_back(&f);
  return stitch_faces(set, pointers);
}

TEST(FaceStitching, AnEdgeAlongAnAxisGetsThePointsInsideItInOrder) {
  AxisPlane p(2);
  // Under the top edge of [0, 2] x [0, 1] (from (2, 1) to (0, 1)), four faces whose corners
  // lie on it at x = 0.5, 1, 1.5; a fifth on its line beyond its end, at x = 3.
  const std::vector<SolidFace> faces{
      face_of(p.set, p.rectangle(0, 0, 2, 1)),   face_of(p.set, p.rectangle(0, 1, 0.5, 2)),
      face_of(p.set, p.rectangle(0.5, 1, 1, 2)), face_of(p.set, p.rectangle(1, 1, 1.5, 2)),
      face_of(p.set, p.rectangle(1.5, 1, 2, 2)), face_of(p.set, p.rectangle(3, 1, 4, 2))};
  const IndexedSoup soup = stitch(p.set, faces);
  ASSERT_EQ(soup.polygons.size(), faces.size());
  EXPECT_EQ(corners(soup, 0),
            (Corners{{0, 0}, {2, 0}, {2, 1}, {1.5, 1}, {1, 1}, {0.5, 1}, {0, 1}}));
  // The bottom edges of the faces above hold no other face's corner inside them.
  EXPECT_EQ(corners(soup, 2), (Corners{{0.5, 1}, {1, 1}, {1, 2}, {0.5, 2}}));
  EXPECT_EQ(corners(soup, 5), (Corners{{3, 1}, {4, 1}, {4, 2}, {3, 2}}));
}

TEST(FaceStitching, ASlantedEdgeGetsAPointOnItsLine) {
  AxisPlane p(2);
  // [0, 2] x [0, 2] with its corner (2, 2) cut off along x + y = 3: a slanted edge from (2, 1)
  // to (1, 2). The triangle beyond it has a corner on that edge, at (1.5, 1.5).
  const Contribution cut = p.corner_cut(0, 0, 2, 2, 1.0, 0);
  const PlaneRef diagonal = cut.polygon.lines[3];
  PlaneRecipe along_y_equals_x;
  along_y_equals_x.kind = PlaneRecipe::Kind::through2;
  along_y_equals_x.v = {2, 2, 0, 0};
  const PlaneRef x2{p.set.add_axis(0, 2.0), 1}, x15{p.set.add_axis(0, 1.5), 1};
  const PlaneRef y_equals_x{p.set.add(along_y_equals_x), 1};
  const std::vector<SolidFace> faces{face_of(p.set, cut.polygon),
                                     face_of(p.set, {p.plane, 1},
                                             {make_point(p.set, p.plane, diagonal.id, x2.id),
                                              make_point(p.set, p.plane, x2.id, y_equals_x.id),
                                              make_point(p.set, p.plane, diagonal.id, x15.id)},
                                             {x2, y_equals_x, {diagonal.id, -diagonal.sign}})};
  const IndexedSoup soup = stitch(p.set, faces);
  EXPECT_EQ(corners(soup, 0), (Corners{{0, 0}, {2, 0}, {2, 1}, {1.5, 1.5}, {1, 2}, {0, 2}}));
  EXPECT_EQ(corners(soup, 1), (Corners{{2, 1}, {2, 2}, {1.5, 1.5}}));
}

}  // namespace
}  // namespace roomcad::detail
