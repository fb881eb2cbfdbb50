// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: building small plans of every kind of degenerate geometry (plan_bytes.h)
// as `--force` builds them, on the automatic path (fast and general paths). The build must
// give a closed 2-manifold wall solid or refuse with a PreconditionError naming why; any
// crash, sanitizer report, hang, other exception or open solid is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz/plan_bytes.h"
#include "modeling/build_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const roomcad::Plan plan = roomcad::fuzz::decode_plan(data, size);
  roomcad::Model model;
  try {
    model = roomcad::build_model(plan, roomcad::BuildOptions{.parts = {true, false, true}, .threads = 1});
  } catch (const roomcad::PreconditionError& e) {
    if (e.code() == roomcad::Code::internal) __builtin_trap();  // an invariant of the build broke
    return 0;
  }
  for (const auto h : model.walls.halfedges())
    if (model.walls.is_boundary(h)) __builtin_trap();  // not closed
  return 0;
}
