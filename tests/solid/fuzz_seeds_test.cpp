// SPDX-License-Identifier: GPL-3.0-or-later
// The committed seeds of fuzz_build and fuzz_render (fuzz/corpus/build/), decoded as the
// targets decode them (fuzz/plan_bytes.h) and built as `--force` builds them on every path:
// degenerate plans (zero-length and hairline walls, bow-ties, coincident and nested walls,
// openings flush with every end, tiny and huge coordinates) build closed or are refused with
// a reason, in every build of the suite, not only when the fuzzers run.
#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fuzz/plan_bytes.h"
#include "support/model_support.h"

namespace roomcad {
namespace {

// The walls built on one path, or the reason they were refused.
struct Outcome {
  std::optional<Model> model;
  std::string refusal;
};

Outcome build_on(const Plan& plan, BooleanPath path) {
  try {
    return {build_model(plan, test::options_for(path, 1)), {}};
  } catch (const PreconditionError& e) {
    EXPECT_NE(e.code(), Code::internal) << e.what();
    EXPECT_NE(std::string(e.what()).find("build_model: "), std::string::npos) << e.what();
    return {std::nullopt, e.what()};
  }
}

TEST(FuzzSeeds, EveryBuildSeedBuildsAsNefDoesOrIsRefusedOnEveryPath) {
  const auto seeds = fuzz::corpus_files(ROOMCAD_SOURCE_DIR "/fuzz/corpus/build");
  ASSERT_GE(seeds.size(), 10u);
  std::set<std::string> refused;   // seeds refused on the automatic path
  std::set<std::string> nef_open;  // seeds built here whose Nef solid, rounded, is open
  for (const auto& seed : seeds) {
    const std::string name = seed.filename().string();
    SCOPED_TRACE(name);
    const Plan plan = fuzz::decode_plan_file(seed);
    const Outcome nef = build_on(plan, BooleanPath::nef);
    for (const BooleanPath path : {BooleanPath::automatic, BooleanPath::general}) {
      SCOPED_TRACE(path == BooleanPath::general ? "general" : "automatic");
      const Outcome made = build_on(plan, path);
      if (!made.model) {
        // Refused only where Nef refuses too, where Nef's solid, rounded to doubles, is no
        // valid solid either, or where a feature finer than the doubles resolve made the
        // written solid fail its check (fine_features.h), named in the refusal.
        const bool written_solid_failed =
            made.refusal.find("fails once its corners are rounded") != std::string::npos;
        if (nef.model && !written_solid_failed) {
          EXPECT_FALSE(check_solid(nef.model->walls).is_valid()) << made.refusal;
        }
        if (path == BooleanPath::automatic) refused.insert(name);
        continue;
      }
      const SolidCheck c = check_solid(made.model->walls);
      EXPECT_TRUE(c.is_closed()) << c.border_edges << " border edges";
      EXPECT_TRUE(c.is_manifold());
      if (!nef.model) {
        // Nef's exact solid, rounded to doubles, is not closed: features finer than that
        // rounding, which the general path builds exactly. Only that refusal, on one seed.
        EXPECT_NE(nef.refusal.find("is not closed"), std::string::npos) << nef.refusal;
        nef_open.insert(name);
        continue;
      }
      const SolidCheck reference = check_solid(nef.model->walls);
      EXPECT_EQ(c.genus, reference.genus);
      EXPECT_NEAR(c.volume, reference.volume,
                  2 * volume_tolerance(nef.model->walls, reference.volume));
    }
  }
  EXPECT_LE(nef_open.size(), 1u);
  // Refused by name: a wall of length 0 (zero-length), walls thinner than 64 units in the last
  // place of their coordinates (far-tiny, crash-far-wall-thinner-than-its-ulps) and walls an
  // ulp long, shorter than that (stress finding S6: bowtie, hairline, crash-rounded-end-3 and
  // crash-ulp-wall-at-reversed-diagonal-walls, which built solids that cross themselves), and
  // a wall over another that ends an ulp past it (crash-ulp-step-between-collinear-wall-ends,
  // whose written solid is open).
  const std::set<std::string> expected{"bowtie",
                                       "crash-far-wall-thinner-than-its-ulps",
                                       "crash-rounded-end-3",
                                       "crash-ulp-step-between-collinear-wall-ends",
                                       "crash-ulp-wall-at-reversed-diagonal-walls",
                                       "far-tiny",
                                       "hairline",
                                       "zero-length"};
  EXPECT_EQ(refused, expected);
}

}  // namespace
}  // namespace roomcad
