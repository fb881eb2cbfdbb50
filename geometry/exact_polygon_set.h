// SPDX-License-Identifier: GPL-3.0-or-later
// ExactPolygonSet: exact union, intersection and difference of plane areas (CGAL's
// Polygon_set_2 over Epeck), behind a small class whose operations are all compiled in
// exact_polygon_set.cpp. CGAL's Boolean set operations are among its heaviest templates: the
// analytic volume and the polygon predicates share this one instantiation instead of each
// compiling their own (bench/report.md has the compile times).
//
// Every operation is regularised, as CGAL's: what only touches (a shared edge or corner) is no
// part of an intersection, and a result has no dangling edges or isolated points.
#pragma once

#include <memory>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace roomcad::detail {

using ExactPolygon = CGAL::Polygon_2<CGAL::Epeck>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<CGAL::Epeck>;

/// A set of disjoint areas of the plane, each an outline with holes.
class ExactPolygonSet {
 public:
  /// The empty set.
  ExactPolygonSet();
  /// The area of `polygon`. @pre simple, counter-clockwise.
  explicit ExactPolygonSet(const ExactPolygon& polygon);
  /// The area of `area`. @pre outline counter-clockwise, holes clockwise, simple, disjoint.
  explicit ExactPolygonSet(const ExactPolygonWithHoles& area);
  ExactPolygonSet(ExactPolygonSet&&) noexcept;
  ExactPolygonSet& operator=(ExactPolygonSet&&) noexcept;
  ~ExactPolygonSet();

  /// Unites every polygon and area given with this set, in one sweep: O((n + k) log n) for n
  /// edges and k crossings. @pre each as the constructors require.
  void join(const std::vector<ExactPolygon>& polygons,
            const std::vector<ExactPolygonWithHoles>& areas);
  /// Keeps only what this set shares with `other`.
  void intersection(const ExactPolygonSet& other);
  /// Takes `other` away from this set.
  void difference(const ExactPolygonSet& other);

  [[nodiscard]] bool is_empty() const;
  /// @return the set's areas, outlines counter-clockwise and holes clockwise.
  [[nodiscard]] std::vector<ExactPolygonWithHoles> polygons_with_holes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace roomcad::detail
