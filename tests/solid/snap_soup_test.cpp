// SPDX-License-Identifier: GPL-3.0-or-later
// snap_soup: corners a few ulps apart snap together, and the fins, needles and pinches that
// leaves are cleaned away without opening the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "solid/detail/assembly/snap_soup.h"

namespace roomcad {
namespace {

using detail::IndexedSoup;
using Polygons = std::vector<std::vector<std::size_t>>;

// Every directed edge used once and paired with its reverse (a closed 2-manifold surface).
bool is_closed(const Polygons& polygons) {
  std::map<std::pair<std::size_t, std::size_t>, int> edges;
  for (const auto& p : polygons)
    for (std::size_t k = 0; k < p.size(); ++k) ++edges[{p[k], p[(k + 1) % p.size()]}];
  for (const auto& [e, n] : edges)
    if (n != 1 || !edges.count({e.second, e.first})) return false;
  return true;
}

double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }

TEST(SnapSoup, SnapToleranceIsFourUlpsOfTheLargestCoordinate) {
  EXPECT_EQ(detail::snap_tolerance({}), 0.0);
  EXPECT_EQ(detail::snap_tolerance({{1.0, -2.0, 0.5}}), 4.0 * (next_up(2.0) - 2.0));
}

// A unit cube whose top is split by a groove one ulp wide: two faces of the groove's walls
// and its floor. Snapping closes the groove; the cube stays closed, with no fin left.
TEST(SnapSoup, SnapClosesAGrooveOneUlpWide) {
  const double h = 0.5, g = next_up(0.5);
  IndexedSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},   // 0-3 bottom
                 {0, 0, 1}, {h, 0, 1}, {h, 1, 1}, {0, 1, 1},   // 4-7 top, left half
                 {g, 0, 1}, {1, 0, 1}, {1, 1, 1}, {g, 1, 1}};  // 8-11 top, right half
  soup.polygons = {{3, 2, 1, 0},       {4, 5, 6, 7},         {8, 9, 10, 11},
                   {0, 1, 9, 8, 5, 4}, {2, 3, 7, 6, 11, 10}, {0, 4, 7, 3},
                   {1, 2, 10, 9},      {5, 8, 11, 6}};  // the groove's floor, one ulp wide
  const IndexedSoup out = detail::snap_soup(soup, detail::snap_tolerance(soup.points));
  EXPECT_EQ(out.polygons.size(), 7u);  // the floor collapsed to an edge
  EXPECT_TRUE(is_closed(out.polygons));
}

TEST(SnapSoup, SnapRemovesAFinOfTwoOppositeFaces) {
  IndexedSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-300, 0, 0}};
  soup.polygons = {{0, 1, 2},
                   {3, 2, 1}};  // 3 snaps onto 0: the two faces are one another's reverse
  EXPECT_TRUE(detail::snap_soup(soup, 1e-200).polygons.empty());
  EXPECT_EQ(detail::snap_soup(soup, 0.0).polygons.size(), 2u);  // nothing within 0
}

TEST(SnapSoup, SnapSplitsAPolygonPinchedAtACorner) {
  IndexedSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {-1, -1, 0}};
  soup.polygons = {{0, 1, 2, 3, 4, 5}};  // 3 is 0: two triangles touching at the origin
  const IndexedSoup out = detail::snap_soup(soup, 0.0);
  ASSERT_EQ(out.polygons.size(), 2u);
  EXPECT_EQ(out.polygons[0], (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(out.polygons[1], (std::vector<std::size_t>{0, 4, 5}));
}

TEST(SnapSoup, SnapDropsSpikesAndRepeatedCorners) {
  IndexedSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 2, 0}};
  soup.polygons = {{0, 1, 1, 2, 3, 2}};  // repeated 1, spike 2 -> 3 -> 2
  const IndexedSoup out = detail::snap_soup(soup, 0.0);
  ASSERT_EQ(out.polygons.size(), 1u);
  EXPECT_EQ(out.polygons[0], (std::vector<std::size_t>{0, 1, 2}));
}

// A unit cube whose front is two faces split at x = 0.5, the left one with a corner at mid
// height on the split, and between them a flat triangle (all three corners on the split
// line), as rounding leaves the side of a sliver. The triangle goes, the right face takes
// the corner, and the cube stays closed.
TEST(SnapSoup, SnapCollapsesAFlatPolygonIntoItsNeighboursEdges) {
  IndexedSoup soup;
  soup.points = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0},   {0, 1, 0},   {0, 0, 1},    {1, 0, 1},
      {1, 1, 1}, {0, 1, 1}, {0.5, 0, 0}, {0.5, 0, 1}, {0.5, 0, 0.5}};  // 8-10 on the split
  soup.polygons = {{3, 2, 1, 8, 0}, {4, 9, 5, 6, 7},  {2, 3, 7, 6}, {0, 4, 7, 3},
                   {1, 2, 6, 5},    {0, 8, 10, 9, 4}, {8, 1, 5, 9},  // the front's two faces
                   {8, 9, 10}};                                      // flat
  soup.tags = {0, 1, 2, 3, 4, 5, 6, 7};
  ASSERT_TRUE(is_closed(soup.polygons));
  const IndexedSoup out = detail::snap_soup(soup, 0.0);
  ASSERT_EQ(out.polygons.size(), 7u);
  EXPECT_TRUE(is_closed(out.polygons));
  EXPECT_EQ(out.polygons[6], (std::vector<std::size_t>{8, 1, 5, 9, 10}));
  EXPECT_EQ(out.tags, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
}

}  // namespace
}  // namespace roomcad
