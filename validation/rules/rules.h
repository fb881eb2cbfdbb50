// SPDX-License-Identifier: GPL-3.0-or-later
// The rules of the rule sets, one file each, run by check_rules (run_rules.cpp) on what
// validate() found. Each appends its findings to the report in a fixed order (by object
// index), so the report does not depend on threads. Plain header.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "validation/report.h"
#include "validation/rules/context.h"
#include "validation/rules/scene.h"

namespace roomcad::rules {

/// door_swing_blocked, door_clearance, door_too_narrow (door_rules.cpp).
void check_doors(const Context& cx, const Scene& scene, Report& report);
/// window_sill_low, window_sill_high (object_rules.cpp).
void check_windows(const Context& cx, const Scene& scene, Report& report);
/// duplicate_object (object_rules.cpp).
void check_duplicates(const Context& cx, const Scene& scene, Report& report);
/// room_unreachable (reachability.cpp).
void check_reachability(const Context& cx, const Scene& scene, Report& report);
/// no_turning_circle (turning_circle.cpp).
void check_turning_circles(const Context& cx, const Scene& scene, Report& report);
/// passage_too_narrow (passages.cpp).
void check_passages(const Context& cx, const Scene& scene, Report& report);
/// escape_too_far (escape.cpp).
void check_escape(const Context& cx, const Scene& scene, Report& report);

/// @return a finding of `code` with the rule set's severity for it.
[[nodiscard]] Diagnostic make_finding(const Context& cx, Code code,
                                      std::vector<std::string> objects, std::string message,
                                      std::string fix, std::vector<FixEdit> edits,
                                      std::optional<Where> where);

/// @return the box of a room's clear outline as a `where`.
[[nodiscard]] Where room_where(const Room& room);

}  // namespace roomcad::rules
