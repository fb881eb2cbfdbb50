// SPDX-License-Identifier: GPL-3.0-or-later
// Trying fixes before proposing them: a fix is only given as edits when, applied to the plan,
// it removes the finding (checked by the rule's own exact test) and introduces no error that
// validation would report. Validation of the whole plan per candidate would cost O(n) each,
// so a candidate is validated on a neighbourhood: the walls near the change, the walls
// joined to those (so that their mitres are the plan's own), and their openings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// A band of heights: a neighbourhood keeps only the walls that reach into it, so that on a
/// home of many storeys the walls above and below (which no edit of this storey meets) are
/// not validated with every candidate.
struct Heights {
  double low = 0.0, high = 0.0;
};

/// @return the heights wall `w` spans: its base to its highest top. O(1).
[[nodiscard]] Heights heights_of(const Wall& w);
/// @return the heights the walls span together. @pre walls not empty. O(walls).
[[nodiscard]] Heights heights_of(const Plan& plan, const std::vector<std::size_t>& walls);

/// The part of a plan near a place, with its errors as they are.
class Neighbourhood {
 public:
  /// @param[in] box      the region an edit may change (e.g. a door's wall grown by its leaf)
  /// @param[in] heights  the heights an edit may change (touching included)
  Neighbourhood(const Scene& scene, const Box2& box, Heights heights);

  [[nodiscard]] const Plan& plan() const { return plan_; }
  /// @return the neighbourhood with the edits applied, if they apply and introduce no error
  ///         that validate() would report there. O(k log k) for k walls nearby.
  [[nodiscard]] std::optional<Plan> try_edits(const std::vector<FixEdit>& edits) const;

 private:
  Plan plan_;
  Report before_;
};

/// @return a length for an edit: the shortest decimal that reads back to the value.
[[nodiscard]] std::string number_text(double value);

/// @return value rounded up (down) to whole centimetres, as the number a fix writes.
[[nodiscard]] double centimetres_up(double value);
[[nodiscard]] double centimetres_down(double value);

/// @return the edits that move wall `wall` by `by` (metres) and with it the ends of the walls
///         that stand on its centre line or share its ends, so that the joins stay.
[[nodiscard]] std::vector<FixEdit> move_wall_edits(const Scene& scene, std::size_t wall, Point2 by);

/// @return "x,y" for a point in an edit.
[[nodiscard]] std::string point_text(Point2 p);

/// @return a set edit of one object.
[[nodiscard]] FixEdit set_edit(std::string id,
                               std::vector<std::pair<std::string, std::string>> fields);

}  // namespace roomcad::rules
