// SPDX-License-Identifier: GPL-3.0-or-later
// The door rules' exact tests, on a scene and an opening that may be a changed copy of one
// of its doors (fixes are tried that way). Plain header; door_tests.cpp holds the geometry.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/broad_phase.h"
#include "plan/plan.h"
#include "validation/rule_set.h"
#include "validation/rules/scene.h"
#include "validation/rules/written_number.h"

namespace roomcad::rules {

/// @return true if the leaf of door `o` in wall `host` sweeps through the interior of wall
///         `wall` where their heights overlap (touching is not hitting). Exact.
[[nodiscard]] bool leaf_hits_wall(const Scene& scene, const Opening& o, std::size_t host,
                                  std::size_t wall, Precision precision = Precision::exact);

/// @return true if the swept quarter discs of doors a and b share interior area where their
///         heights overlap. Exact.
[[nodiscard]] bool leaves_meet(const Scene& scene, const Opening& a, std::size_t host_a,
                               const Opening& b, std::size_t host_b,
                               Precision precision = Precision::exact);

/// @return true if the clear rectangle in front of door `o` (push side) shares interior area
///         with wall `wall`, among walls people walk into (kHeadroom above the door's floor).
[[nodiscard]] bool clearance_hits_wall(const Scene& scene, const Opening& o, std::size_t host,
                                       std::size_t wall, const RuleThresholds& thresholds,
                                       Precision precision = Precision::exact);

/// (Precision::approximate evaluates in doubles: for sorting out candidate fixes only.)

/// Outward-rounded boxes of the leaf's quarter square and of the clear rectangle.
[[nodiscard]] Box2 leaf_box(const Scene& scene, const Opening& o, std::size_t host);
[[nodiscard]] Box2 clearance_box(const Scene& scene, const Opening& o, std::size_t host,
                                 const RuleThresholds& thresholds);

/// @return the walls other than the host that the leaf hits, sorted.
[[nodiscard]] std::vector<std::size_t> walls_hit_by_leaf(const Scene& scene, const Opening& o,
                                                         std::size_t host,
                                                         Precision precision = Precision::exact);
/// @return the walls other than the host in the clear rectangle, sorted.
[[nodiscard]] std::vector<std::size_t> walls_in_clearance(const Scene& scene, const Opening& o,
                                                          std::size_t host,
                                                          const RuleThresholds& thresholds,
                                                          Precision precision = Precision::exact);

/// @return true if door `o`'s width is below `min_width` in the written numbers.
[[nodiscard]] bool is_narrower(double width, double min_width);

}  // namespace roomcad::rules
