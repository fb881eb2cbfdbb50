// Validation of a plan: every error code and warning of ../shared/spec/plan-format.md, all
// problems in one run, verdicts exact for the coordinates as read.
#pragma once

#include <vector>

#include "modeling/plan.h"
#include "validation/report.h"
#include "validation/rule_set.h"

namespace roomcad {

struct ValidateOptions {
  bool room_warnings = true;  ///< find rooms and warn about rooms with no door or no window
  /// warn about the fields kept in `extra`; the plan reader already reports them (with line
  /// and column), so commands that read a file turn this off.
  bool unknown_field_warnings = true;
  /// The rules beyond the plan format's checks (validation/rule_set.h); the default set has
  /// none. Rule findings are warnings unless the set says "error" for a rule. ({}: may be left
  /// out of designated initializers without a warning.)
  RuleSet rules{};
};

/// Checks a plan. Never throws on any Plan value (NaN, negative sizes, dangling references
/// are reported, not assumed away). Cost O(n log n + k) for n objects and k nearby pairs,
/// plus the rules' searches (each finding's fix is tried near it).
[[nodiscard]] Report validate(const Plan& plan, const ValidateOptions& options = {});

/// A closed region of the wall arrangement (a room), as a simple polygon on the wall faces
/// that bound it, counter-clockwise, in metres.
struct Room {
  std::vector<Point2> outline;           ///< the clear floor: centre-line face moved inward
                                         ///< by each bounding wall's half-thickness
  double area = 0.0;                     ///< clear floor area, square metres (rooms nested
                                         ///< inside are subtracted by their centre-line area)
  std::vector<std::string> walls;        ///< ids of the walls bounding it
  std::vector<std::string> doors;        ///< ids of doors in those walls
  std::vector<std::string> windows;      ///< ids of windows in those walls
};

/// Finds the rooms of a plan: bounded faces of the walls' centre-line arrangement, numbered
/// from the south-west. Meant for a plan that validates without errors; on any other it
/// skips walls that are not drawable and does not throw. A room's doors and windows are the
/// openings on the pieces of wall that bound it. O(n log n) in walls.
[[nodiscard]] std::vector<Room> find_rooms(const Plan& plan);

}  // namespace roomcad
