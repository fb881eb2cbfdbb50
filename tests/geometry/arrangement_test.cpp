// SPDX-License-Identifier: GPL-3.0-or-later
// find_bounded_faces: pieces that meet only at their ends (inserted without looking for
// crossings) and pieces that cross, touch inside or overlap (the exact arrangement) give the
// same rooms.
#include "geometry/detail/arrangement.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace roomcad::detail {
namespace {

using Segments = std::vector<std::pair<Point2, Point2>>;

double area_of(const Face& face) {
  double twice = 0;
  for (const FaceEdge& e : face.boundary)
    twice += e.source.x * e.target.y - e.source.y * e.target.x;
  return twice / 2;
}

/// The faces' areas (counter-clockwise outer boundaries: positive), smallest first.
std::vector<double> areas(const std::vector<Face>& faces) {
  std::vector<double> out;
  for (const Face& f : faces) out.push_back(area_of(f));
  std::sort(out.begin(), out.end());
  return out;
}

/// Every edge of every face lies on the piece it names.
void expect_edges_on_their_pieces(const std::vector<Face>& faces, const Segments& pieces) {
  for (const Face& f : faces)
    for (const FaceEdge& e : f.boundary) {
      ASSERT_LT(e.wall, pieces.size());
      const auto& [a, b] = pieces[e.wall];
      for (const Point2 p : {e.source, e.target})
        EXPECT_EQ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), 0.0)
            << "(" << p.x << ", " << p.y << ") is not on piece " << e.wall;
    }
}

/// A 4 x 4 square cut into four 2 x 2 rooms by a cross, drawn as whole lines that cross at
/// (2, 2) and meet the sides inside them.
const Segments kCrossing = {{{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}},
                            {{0, 4}, {0, 0}}, {{0, 2}, {4, 2}}, {{2, 0}, {2, 4}}};

/// The same rooms drawn as pieces that meet only at their ends.
const Segments kEndToEnd = {{{0, 0}, {2, 0}}, {{2, 0}, {4, 0}}, {{4, 0}, {4, 2}}, {{4, 2}, {4, 4}},
                            {{4, 4}, {2, 4}}, {{2, 4}, {0, 4}}, {{0, 4}, {0, 2}}, {{0, 2}, {0, 0}},
                            {{0, 2}, {2, 2}}, {{2, 2}, {4, 2}}, {{2, 0}, {2, 2}}, {{2, 2}, {2, 4}}};

TEST(Arrangement, PiecesEndToEndAndCrossingLinesGiveTheSameRooms) {
  const std::vector<Face> end_to_end = find_bounded_faces(kEndToEnd);
  const std::vector<Face> crossing = find_bounded_faces(kCrossing);
  EXPECT_EQ(areas(end_to_end), (std::vector<double>{4, 4, 4, 4}));
  EXPECT_EQ(areas(crossing), areas(end_to_end));
  expect_edges_on_their_pieces(end_to_end, kEndToEnd);
  expect_edges_on_their_pieces(crossing, kCrossing);
  for (const Face& f : end_to_end) EXPECT_EQ(f.boundary.size(), 4u);
}

TEST(Arrangement, AnEndInsideAnotherPieceIsAJunction) {
  // A T: the middle wall's end stands on the south side without a piece ending there.
  const Segments t = {
      {{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}}, {{0, 4}, {0, 0}}, {{2, 0}, {2, 4}}};
  EXPECT_EQ(areas(find_bounded_faces(t)), (std::vector<double>{8, 8}));
}

TEST(Arrangement, PiecesDrawnTwiceOrOverlappingNameTheLowestPiece) {
  // The south side drawn twice (pieces 0 and 4), and overlapped along its first half by a
  // piece sharing its west end (piece 5).
  const Segments twice = {{{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}},
                          {{0, 4}, {0, 0}}, {{4, 0}, {0, 0}}, {{0, 0}, {2, 0}}};
  const std::vector<Face> faces = find_bounded_faces(twice);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(area_of(faces[0]), 16);
  for (const FaceEdge& e : faces[0].boundary) {
    if (e.source.y == 0 && e.target.y == 0) {
      EXPECT_EQ(e.wall, 0u);
    }
  }
}

TEST(Arrangement, ARoomInsideARoomIsAHoleOfIt) {
  // Two squares that do not meet: the inner one is a hole in the outer one's face.
  const Segments nested = {{{0, 0}, {10, 0}}, {{10, 0}, {10, 10}}, {{10, 10}, {0, 10}},
                           {{0, 10}, {0, 0}}, {{4, 4}, {6, 4}},    {{6, 4}, {6, 6}},
                           {{6, 6}, {4, 6}},  {{4, 6}, {4, 4}}};
  const std::vector<Face> faces = find_bounded_faces(nested);
  ASSERT_EQ(faces.size(), 2u);
  const auto outer = std::max_element(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return area_of(a) < area_of(b);
  });
  EXPECT_EQ(area_of(*outer), 100);
  EXPECT_EQ(outer->hole_area, 4);
  EXPECT_EQ(faces[outer == faces.begin() ? 1 : 0].hole_area, 0);
}

TEST(Arrangement, PiecesLeavingAnEndInOneDirectionOverlap) {
  // Pieces 0 and 4 share the end (0, 0) and run east along one line: not end to end.
  const Segments overlap = {
      {{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}}, {{0, 4}, {0, 0}}, {{0, 0}, {1, 0}}};
  const std::vector<Face> faces = find_bounded_faces(overlap);
  ASSERT_EQ(areas(faces), (std::vector<double>{16}));
  expect_edges_on_their_pieces(faces, overlap);
  // The south side is cut where piece 4 ends; both of its edges name piece 0, the lower.
  EXPECT_EQ(faces[0].boundary.size(), 5u);
  for (const FaceEdge& e : faces[0].boundary) {
    if (e.source.y == 0 && e.target.y == 0) {
      EXPECT_EQ(e.wall, 0u);
    }
  }
}

}  // namespace
}  // namespace roomcad::detail
