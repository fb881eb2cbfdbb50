// SPDX-License-Identifier: GPL-3.0-or-later
// Stress report: how many of fuzz_build's degenerate plans (fuzz/plan_bytes.h) build a solid
// that `roomcad build --check` fails (open, not 2-manifold, self-intersecting, degenerate or
// inside out once triangulated, or off the analytic volume by more than volume_tolerance).
// Each plan is 64 bytes from mt19937_64(seed), its scale byte set to 1, 10 or 0.25 m (the
// scales of hand-drawn plans; far and tiny coordinates still come from the shift and the
// tables), built as fuzz_build builds it (automatic path, walls and fixtures, one thread).
// build_model checks plans finer than their doubles itself (fine_features.h) and refuses those
// whose solid fails; the summary counts both.
// Run: build/bench/fuzz_plans_check_bench [PLANS [SEED]]      (default 20000 plans, seed 5)
//      build/bench/fuzz_plans_check_bench PLANS SEED INDEX -o plan.json
// The first prints the counts and each failing plan's index and check; the second writes
// plan INDEX as plan JSON, for `roomcad build --force --check plan.json`.
// Stress finding S6 (docs/stress-findings.md) quotes its figures.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string_view>
#include <vector>

#include "fuzz/plan_bytes.h"
#include "io/plan_json.h"
#include "solid/build_model.h"
#include "solid/detail/frames/fine_features.h"
#include "solid/wall_check.h"

namespace {

using namespace roomcad;

// How build_model words a refusal after its check of the solid as written (build_model.cpp).
constexpr std::string_view kRefusedAsWritten = "fails once its corners are rounded to doubles";

/// @return the next plan drawn from `rng`.
Plan next_plan(std::mt19937_64& rng) {
  constexpr std::array<std::uint8_t, 3> kHandDrawnScales{0, 2, 5};  // indices into fuzz::kScales
  std::array<std::uint8_t, 64> bytes{};
  for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
  bytes[0] = kHandDrawnScales[bytes[0] % kHandDrawnScales.size()];
  return fuzz::decode_plan(bytes.data(), bytes.size());
}

int write_one(long plans, unsigned seed, long index, const char* path) {
  std::mt19937_64 rng(seed);
  Plan plan;
  for (long i = 0; i <= index && i < plans; ++i) plan = next_plan(rng);
  const Status written = write_plan_file(plan, path);
  if (!written.ok()) {
    std::fprintf(stderr, "fuzz_plans_check_bench: %s\n", written.message().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const long plans = argc > 1 ? std::atol(argv[1]) : 20000;
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atol(argv[2])) : 5u;
  if (argc == 6 && std::strcmp(argv[4], "-o") == 0)
    return write_one(plans, seed, std::atol(argv[3]), argv[5]);
  if (argc > 3 || plans <= 0) {
    std::fprintf(stderr,
                 "usage: fuzz_plans_check_bench [PLANS [SEED]] | PLANS SEED INDEX -o plan.json\n");
    return 2;
  }
  std::mt19937_64 rng(seed);
  long built = 0, failed = 0, fine = 0, refused_as_written = 0;
  for (long i = 0; i < plans; ++i) {
    const Plan plan = next_plan(rng);
    Model model;
    try {
      model = build_model(plan, BuildOptions{.parts = {true, false, true}, .threads = 1});
    } catch (const PreconditionError& e) {
      // Refused by name, as fuzz_build allows; some after build_model's own check of a plan
      // finer than its doubles (fine_features.h).
      refused_as_written +=
          std::string_view(e.what()).find(kRefusedAsWritten) != std::string_view::npos;
      continue;
    }
    ++built;
    fine += detail::fine_feature(plan).has_value();
    const WallCheck c = check_walls(model, plan);
    if (c.ok) continue;
    ++failed;
    std::printf(
        "plan %ld: border edges %zu, non-manifold %zu, rejected %zu, degenerate %zu, "
        "self-intersections %zu, inward %zu, volume off by %.3g (limit %.3g)\n",
        i, c.solid.border_edges, c.solid.non_manifold_vertices, c.solid.rejected_triangles,
        c.solid.degenerate_triangles, c.solid.self_intersections, c.solid.inward_components,
        c.relative, c.limit / std::max(c.analytic, 1e-300));
  }
  std::printf(
      "seed %u: %ld plans, %ld built, %ld refused, %ld fail the check; %ld built with a "
      "feature finer than the doubles (checked as written), %ld refused so\n",
      seed, plans, built, plans - built, failed, fine, refused_as_written);
  return 0;
}
