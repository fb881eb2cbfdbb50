// SPDX-License-Identifier: GPL-3.0-or-later
// Fixes for the door rules: another hinge side or swing, a place along the wall, or a width,
// each tried (door_tests.h, and validation of the neighbourhood) before it is proposed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "geometry/box_grid.h"
#include "validation/report.h"
#include "validation/rules/context.h"
#include "validation/rules/scene.h"
#include "validation/rules/written_number.h"

namespace roomcad::rules {

struct DoorFix {
  std::string text;            ///< what to do, in words
  std::vector<FixEdit> edits;  ///< the same as edits
};

class DoorFixer {
 public:
  /// O(1): the leaves of the doors are indexed on the first search (O(n)).
  DoorFixer(const Context& cx, const Scene& scene) : cx_(cx), scene_(scene) {}

  /// A fix for door `door` (an opening index) under rule `code` (door_swing_blocked or
  /// door_clearance): the first candidate, in order (hinge side, swing, both; then places
  /// along the wall, nearest first) that clears the door for every enabled door rule, or
  /// failing that for `code` alone, and adds no validation error. Cost: up to a few
  /// thousand exact tests near the door.
  [[nodiscard]] std::optional<DoorFix> find(std::size_t door, Code code) const;

  /// A fix for door_too_narrow: the door made `min_width` wide (rounded up to centimetres),
  /// keeping its middle, its start or its end, whichever fits its wall first.
  [[nodiscard]] std::optional<DoorFix> widen(std::size_t door) const;

 private:
  struct Needs {
    bool swing = false;
    bool clearance = false;
  };
  [[nodiscard]] bool passes(std::size_t door, const Opening& changed, Needs needs,
                            Precision precision) const;
  [[nodiscard]] Needs all_needs(std::size_t door) const;
  [[nodiscard]] std::optional<DoorFix> first_fix(std::size_t door,
                                                 const std::vector<Opening>& candidates,
                                                 Needs own) const;

  [[nodiscard]] const BoxGrid& leaves() const;

  const Context& cx_;
  const Scene& scene_;
  mutable std::optional<BoxGrid> leaves_;  ///< the leaf boxes of the doors (index: opening)
};

}  // namespace roomcad::rules
