// wall_footprint: mitred corners constructed exactly (exact::Radical), then rounded to nearest.
#include <cmath>
#include <limits>
#include <optional>

#include "modeling/exact_geometry.h"
#include "modeling/joins.h"

namespace roomcad {
namespace {

/// Corners that interval arithmetic pins to single doubles (axis-aligned walls, mostly) are
/// exact already; @return them, or nothing when any interval has width.
std::optional<std::array<Point2, 4>> find_exact_corners_fast(const Plan& plan, const Joins& joins,
                                                             std::size_t wall) {
  CGAL::Protect_FPU_rounding<true> upward;
  try {
    const auto corners = exact::wall_corners<exact::Approx>(plan, joins, wall);
    std::array<Point2, 4> out;
    for (std::size_t i = 0; i < 4; ++i) {
      if (!corners[i].x.is_point() || !corners[i].y.is_point()) return std::nullopt;
      out[i] = {corners[i].x.inf(), corners[i].y.inf()};
    }
    return out;
  } catch (const CGAL::Uncertain_conversion_exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::array<Point2, 4> wall_footprint(const Plan& plan, const Joins& joins, std::size_t wall) {
  if (const auto fast = find_exact_corners_fast(plan, joins, wall)) return *fast;
  const exact::Exact::Scope scope;
  const std::array<exact::Pt<exact::Exact>, 4> corners =
      exact::wall_corners<exact::Exact>(plan, joins, wall);
  std::array<Point2, 4> out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = {exact::round_to_nearest(corners[i].x), exact::round_to_nearest(corners[i].y)};
  return out;
}

}  // namespace roomcad
