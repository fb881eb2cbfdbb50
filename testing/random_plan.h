// SPDX-License-Identifier: GPL-3.0-or-later
// Seeded random plans for tests: every field of the format exercised, including awkward values.
#pragma once

#include <cstdint>

#include "plan/plan.h"

namespace roomcad::samples {

struct RandomPlanOptions {
  std::size_t max_walls = 12;
  std::size_t max_openings = 8;
  std::size_t max_lights = 3;
  std::size_t max_cameras = 3;
  bool awkward_numbers = true;  ///< -0, subnormals, huge and tiny magnitudes, random bit patterns
  bool awkward_strings = true;  ///< quotes, backslashes, control characters, '/', '~', UTF-8
  bool extras = true;           ///< unknown fields (canonical JSON) at every level
};

/// A plan whose every field is random (finite numbers; any geometry, valid or not), the same
/// for the same seed on every machine. Extra fields hold canonical JSON text (as the reader
/// keeps it) under keys that the format does not use, so a plan written and read back is equal
/// to this one.
[[nodiscard]] Plan random_plan(std::uint64_t seed, const RandomPlanOptions& options = {});

}  // namespace roomcad::samples
