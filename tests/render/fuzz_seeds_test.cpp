// SPDX-License-Identifier: GPL-3.0-or-later
// The committed seeds of fuzz_render (fuzz/corpus/render/), run as the target runs them
// (fuzz/fuzz_render.cpp): each decoded plan that builds is rendered with shadows in a small
// frame, and every depth is finite. The sanitized suite runs them under ASan and UBSan, so a
// seed that once gave a NaN screen coordinate is caught in every build, not only when the
// fuzzers run.
#include <cmath>

#include <gtest/gtest.h>

#include "fuzz/plan_bytes.h"
#include "render/renderer.h"
#include "solid/build_model.h"

namespace roomcad {
namespace {

TEST(RenderFuzzSeeds, EveryRenderSeedThatBuildsRendersFiniteDepths) {
  const auto seeds = fuzz::corpus_files(ROOMCAD_SOURCE_DIR "/fuzz/corpus/render");
  ASSERT_GE(seeds.size(), 10u);
  int rendered = 0;
  for (const auto& seed : seeds) {
    SCOPED_TRACE(seed.filename().string());
    BuildOptions build;
    build.threads = 1;
    Model model;
    try {
      model = build_model(fuzz::decode_plan_file(seed), build);
    } catch (const PreconditionError& e) {
      EXPECT_NE(e.code(), Code::internal) << e.what();
      continue;
    }
    RenderOptions options;
    options.width = 48;
    options.height = 32;
    options.shadow_resolution = 128;
    options.threads = 1;
    FrameBuffers frame;
    render_model(model, options, frame);
    ASSERT_EQ(frame.depth.values.size(), 48u * 32u);
    for (const float d : frame.depth.values) ASSERT_TRUE(std::isfinite(d) && d >= 0.f) << d;
    ++rendered;
  }
  EXPECT_GE(rendered, 10);
}

}  // namespace
}  // namespace roomcad
