// SPDX-License-Identifier: GPL-3.0-or-later
// Shared helpers of the floor plan: the map from plan metres to paper millimetres, small vector
// arithmetic, and the parts of the drawing built from walls and from dimensions.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "geometry/joins.h"
#include "render/floor_plan.h"

namespace roomcad::detail {

inline Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(double k, Point2 a) { return {k * a.x, k * a.y}; }
inline double dot(Point2 a, Point2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Point2 a, Point2 b) { return a.x * b.y - a.y * b.x; }
inline double length(Point2 a) { return std::hypot(a.x, a.y); }
/// @return the vector turned a quarter turn counter-clockwise (in a y-up frame).
inline Point2 left_normal(Point2 a) { return {-a.y, a.x}; }

/// Plan metres (y north, up) to paper millimetres (y down): north at the top of the page.
struct PaperMap {
  double mm_per_m = 20.0;  ///< 1000 / scale
  double left = 0.0;       ///< paper x of plan x = x_min
  double top = 0.0;        ///< paper y of plan y = y_max
  double x_min = 0.0;
  double y_max = 0.0;

  [[nodiscard]] Point2 to_paper(Point2 m) const {
    return {left + (m.x - x_min) * mm_per_m, top + (y_max - m.y) * mm_per_m};
  }
  [[nodiscard]] PaperPolygon to_paper(const std::vector<Point2>& metres) const {
    PaperPolygon out;
    out.reserve(metres.size());
    for (const Point2& p : metres) out.push_back(to_paper(p));
    return out;
  }
};

/// Adds the cut walls, the walls below and above the cut, the window symbols and the doors.
/// @pre the plan validates; O(n log n) in walls and openings.
void draw_plan_walls(const Plan& plan, const Joins& joins, const FloorPlanOptions& options,
                     const PaperMap& map, FloorPlanDrawing& out);

/// Adds a dimension of the plan segment [a, b] (metres): extension lines, the dimension line
/// `offset_mm` from the segment on the side of `side` (a plan direction), ticks and the length
/// in metres with two decimals. Zero-length segments add nothing.
void add_dimension(Point2 a, Point2 b, Point2 side, double offset_mm, const PaperMap& map,
                   FloorPlanDrawing& out);

/// @return the length as the plan shows it: metres with two decimals ("3.50").
[[nodiscard]] std::string format_metres(double metres);

}  // namespace roomcad::detail
