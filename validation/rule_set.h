// SPDX-License-Identifier: GPL-3.0-or-later
// Rule sets of `roomcad validate --rules NAME|FILE`: which rules run beyond the plan format's
// checks, their thresholds, and their severities. Built-in sets are `default` (no rules: what
// validate always did), `accessibility` and `all`; a rules file (JSON, docs/plan-format.md,
// "Rule sets") starts from one of them, enables or disables rules and sets thresholds.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad {

/// The rule codes, in the order the plan format lists them.
inline constexpr std::array<Code, 11> kRuleCodes = {
    Code::door_swing_blocked, Code::door_clearance,    Code::door_too_narrow,
    Code::passage_too_narrow, Code::no_turning_circle, Code::room_unreachable,
    Code::escape_too_far,     Code::window_sill_low,   Code::window_sill_high,
    Code::duplicate_object,   Code::insolation_short};

/// @return the index of a rule code in kRuleCodes, or nullopt for any other code. O(1).
[[nodiscard]] std::optional<std::size_t> rule_index(Code code);

/// Thresholds, metres. The spec's defaults; the sill limits are roomcad's (docs/plan-format.md).
struct RuleThresholds {
  double clearance_width = 1.5;  ///< free rectangle in front of a door, along the wall
  double clearance_depth = 1.5;  ///< ... and away from it, on the push side
  double door_min_width = 0.80;  ///< a door's clear width (its `width`)
  double passage_min_width = 0.90;
  double turning_diameter = 1.5;
  double escape_max_distance = 30.0;
  double window_min_sill = 0.80;  ///< below: a fall risk without a guard
  double window_max_sill = 1.20;  ///< above: no view and no escape through it
  friend bool operator==(const RuleThresholds&, const RuleThresholds&) = default;
};

/// Which rooms a person stays in: those room_without_window asks a window of. A room named by
/// the plan's `rooms` is one unless a word of its name is in `not_habitable` ("Bath",
/// "Walk-in closet"); an unnamed room is one unless it is under `min_area` or a corridor (at
/// most `corridor_width` wide and three times as long). docs/plan-format.md, "Rule sets".
struct HabitableRooms {
  double min_area = 6.0;        ///< square metres of clear floor
  double corridor_width = 1.8;  ///< metres
  /// Words of room names, lower case; a word with a final "s" matches too ("stairs").
  std::vector<std::string> not_habitable = {
      "hall",    "hallway",   "corridor", "entry",     "entrance",  "foyer",
      "lobby",   "vestibule", "closet",   "wardrobe",  "dressing",  "store",
      "storage", "storeroom", "pantry",   "bath",      "bathroom",  "shower",
      "wc",      "toilet",    "lavatory", "restroom",  "washroom",  "laundry",
      "utility", "garage",    "stair",    "staircase", "stairwell", "landing",
      "boiler",  "cellar",    "balcony",  "terrace",   "porch",     "loggia"};
  friend bool operator==(const HabitableRooms&, const HabitableRooms&) = default;
};

/// The insolation rule (insolation_short): how much direct sun a room needs, on which days,
/// and which rooms; run on the built model by daylight/insolation_rule.h, only for a plan
/// whose site has a location. docs/plan-format.md, "Rule sets". The defaults are EN 17037's
/// minimum: 1.5 hours on 21 March.
struct InsolationRule {
  /// The days checked, `MM-DD` (in kInsolationReferenceYear) or `YYYY-MM-DD`: one date, or a
  /// period's first and last days (the worse of the two counts).
  std::vector<std::string> dates = {"03-21"};
  double min_continuous_hours = 1.5;
  /// Interrupted sun passes too when the periods of at least min_period_hours add up to
  /// this; unset: only continuous sun counts.
  std::optional<double> min_total_hours;
  double min_period_hours = 1.0;
  double ignore_after_sunrise_minutes = 0.0;  ///< sun this soon after sunrise does not count
  double ignore_before_sunset_minutes = 0.0;  ///< nor this close to sunset
  /// The rooms it applies to: names matching this (ECMAScript regular expression, any case);
  /// empty: the habitable rooms (HabitableRooms).
  std::string room_pattern;
  double min_area = 0.0;     ///< square metres of clear floor, at least
  double above_sill = 0.0;   ///< the calculation point, metres up from the sill
  double into_reveal = 0.0;  ///< ... and from the room-side face towards the outside
  friend bool operator==(const InsolationRule&, const InsolationRule&) = default;
};

/// The year an `MM-DD` date of the insolation rule is evaluated in: the sun's path on one
/// date differs between years by well under a minute of sunshine.
inline constexpr int kInsolationReferenceYear = 2026;

struct RuleSet {
  std::string name = "default";  ///< the built-in set's name or the rules file's path
  std::array<bool, kRuleCodes.size()> enabled{};
  /// Severity of each rule's findings: warnings unless a rules file says "error".
  std::array<Severity, kRuleCodes.size()> severity{};
  RuleThresholds thresholds;
  /// Points (x, y) inside the rooms the accessibility rules apply to; unset: every room.
  std::optional<std::vector<Point2>> accessible_rooms;
  /// The rooms room_without_window applies to (the format's check, in every set).
  HabitableRooms habitable_rooms;
  InsolationRule insolation;

  RuleSet() { severity.fill(Severity::warning); }
  [[nodiscard]] bool is_enabled(Code code) const;
  [[nodiscard]] bool any_enabled() const;
  friend bool operator==(const RuleSet&, const RuleSet&) = default;
};

/// @return the names of the built-in sets: default, accessibility, insolation, all.
[[nodiscard]] std::vector<std::string_view> builtin_rule_set_names();

/// @return the built-in set `name`, or nullopt if there is none by that name. O(1).
/// `accessibility`: door_too_narrow, door_clearance, passage_too_narrow, no_turning_circle and
/// room_unreachable; `insolation`: insolation_short; `all`: every rule.
[[nodiscard]] std::optional<RuleSet> builtin_rule_set(std::string_view name);

/// Reads a rules file (format in docs/plan-format.md, "Rule sets: what roomcad decides").
/// @param[in] text  the file's bytes
/// @param[in] file  its path, for messages
/// @return the rule set, or a usage_error naming the file, the field (a JSON pointer) and the
///         value: not JSON, an unknown field or rule (with the nearest known name), a
///         threshold that is not a positive finite number of metres, an unknown severity or
///         base set. O(size of the text).
[[nodiscard]] Result<RuleSet> parse_rule_set(std::string_view text, const std::string& file);

/// @return success, or a usage_error naming the rules file, `/accessible_rooms/i` and the
///         point, for the first accessible-room point that lies in no room of the plan (on any
///         storey). O(n log n) per storey (find_rooms).
[[nodiscard]] Status check_accessible_rooms(const Plan& plan, const RuleSet& rules);

}  // namespace roomcad
