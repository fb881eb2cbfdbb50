// SPDX-License-Identifier: GPL-3.0-or-later
// Rounding an exact boolean result to doubles: where two exact corners lie a few ulps apart
// (walls meeting nearly collinear leave grooves and slivers that thin), their rounded faces
// are zero-width fins and needles that no mesh can hold. Snapping such corners together
// collapses them to the edges and points they really are.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <OpenMesh/Core/Geometry/VectorT.hh>

namespace roomcad::detail {

/// Points and polygons over them (indices), each polygon counter-clockwise from outside.
struct IndexedSoup {
  std::vector<OpenMesh::Vec3d> points;
  std::vector<std::vector<std::size_t>> polygons;
  /// Optional, one per polygon (what face it came from): snap_soup carries each to the
  /// polygons its polygon becomes.
  std::vector<std::size_t> tags;
  /// Optional: whether point i is its exact corner, not a rounding of it. Two such points are
  /// distinct corners of the exact solid, so they are never snapped together, however near
  /// (walls drawn an ulp apart stay apart, as they are). Asked only of points within the
  /// tolerance of another (few: an exact answer can cost an exact construction).
  std::function<bool(std::size_t)> is_exact;
};

/// Snaps together points within `tolerance` of each other (per coordinate, transitively; each
/// group takes the coordinates of its lowest-index point), then cleans the polygons:
/// repeated corners dropped, spikes (a, b, a) removed, a polygon pinched at a repeated corner
/// split in two, polygons of fewer than three corners dropped, polygons with every corner on
/// one line (exactly) dropped with their corners inserted into the edges of the others that
/// run along that line, and pairs of polygons that are one another's reverse (a fin of zero
/// width) removed both.
/// @param[in] soup       points in metres; a closed surface stays closed (collapsing an edge
///                       or a fin keeps every remaining edge paired).
/// @param[in] tolerance  metres, >= 0; a few ulps of the largest coordinate (snap_tolerance).
/// If that leaves an edge not used exactly once each way (two exact corners merged pinch the
/// surface: walls an ulp apart) and the soup says which points are exact, it snaps again
/// keeping exact points in separate groups (a group with one takes its coordinates), and
/// takes that result where it has every edge paired.
/// @return the cleaned soup: same points (unused ones stay), fewer or equal polygons, in the
///         input's order. O(n) expected for n corners (hashing), twice where it snaps again;
///         deterministic.
[[nodiscard]] IndexedSoup snap_soup(IndexedSoup soup, double tolerance);

/// @return 4 ulps of the largest coordinate magnitude in `points` (0 for none). O(n).
[[nodiscard]] double snap_tolerance(const std::vector<OpenMesh::Vec3d>& points);

}  // namespace roomcad::detail
