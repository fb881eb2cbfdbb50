// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: building small plans of every kind of degenerate geometry (plan_bytes.h)
// as `--force` builds them, on the automatic path (fast and general paths). The build must
// give a wall solid that passes `roomcad build --check` (closed, 2-manifold, no faces that
// cross or fold, outward, the analytic volume within what rounding allows: check_walls) or
// refuse with a PreconditionError naming why; any crash, sanitizer report, hang, other
// exception or solid that fails the check is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz/plan_bytes.h"
#include "solid/build_model.h"
#include "solid/wall_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const roomcad::Plan plan = roomcad::fuzz::decode_plan(data, size);
  roomcad::Model model;
  try {
    model = roomcad::build_model(plan,
                                 roomcad::BuildOptions{.parts = {true, false, true}, .threads = 1});
  } catch (const roomcad::PreconditionError& e) {
    if (e.code() == roomcad::Code::internal) __builtin_trap();  // an invariant of the build broke
    return 0;
  }
  if (!roomcad::check_walls(model, plan).ok) __builtin_trap();  // not the spec's solid as written
  return 0;
}
