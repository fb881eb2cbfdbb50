// SPDX-License-Identifier: GPL-3.0-or-later
// What the proposers of one round of repair read: the plan as it stands, its walls' joins and
// openings, its objects by id, and the round's findings.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "geometry/joins.h"
#include "plan/plan.h"
#include "plan/plan_objects.h"
#include "validation/report.h"

namespace roomcad::detail {

struct RepairContext {
  RepairContext(const Plan& plan, double tolerance, const std::vector<Diagnostic>& errors);

  const Plan& plan;
  double tolerance;
  Joins joins;
  OpeningsByWall openings;  ///< per wall index
  std::unordered_map<std::string_view, std::size_t> walls_by_id, openings_by_id,
      slabs_by_id;  ///< the first object of each id
  /// The pairs of walls (lower index first) of the round's wall_overlap findings.
  std::set<std::pair<std::size_t, std::size_t>> overlapping_walls;
  /// @return whether walls a and b are one of those pairs.
  [[nodiscard]] bool overlap(std::size_t a, std::size_t b) const {
    return overlapping_walls.contains(std::minmax(a, b));
  }

  [[nodiscard]] std::optional<std::size_t> wall(std::string_view id) const;
  [[nodiscard]] std::optional<std::size_t> opening(std::string_view id) const;
  [[nodiscard]] std::optional<std::size_t> slab(std::string_view id) const;
  /// @return the id of a wall other than `other` that wall `w` is joined to at its end point
  ///         `end`, if any: moving that end would break the join.
  [[nodiscard]] std::optional<std::string> joined_at(std::size_t w, Point2 end,
                                                     std::size_t other) const;
};

}  // namespace roomcad::detail
