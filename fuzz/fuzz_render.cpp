// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: small plans of degenerate geometry (plan_bytes.h) built as `--force`
// builds them, then rendered in a small frame (shadows on, the default camera framing them).
// Any crash, sanitizer report, hang or exception other than a refusal to build is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz/plan_bytes.h"
#include "render/renderer.h"
#include "solid/build_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const roomcad::Plan plan = roomcad::fuzz::decode_plan(data, size);
  roomcad::Model model;
  try {
    model = roomcad::build_model(plan, roomcad::BuildOptions{.threads = 1});
  } catch (const roomcad::PreconditionError&) {
    return 0;
  }
  roomcad::RenderOptions options;
  options.width = 48;
  options.height = 32;
  options.shadow_resolution = 128;
  options.threads = 1;
  roomcad::FrameBuffers frame;
  roomcad::render_model(model, options, frame);
  return 0;
}
