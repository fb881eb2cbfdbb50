// SPDX-License-Identifier: GPL-3.0-or-later
// The STL of every bundled example and imported home, as an independent reader sees it: admesh
// (Debian package `admesh`, installed by scripts/setup.sh) reads the file, welds it by
// coordinates, and reports degenerate facets (two equal corners), unconnected facet edges and
// what it had to repair. Flat facets with three distinct corners on a line, which admesh does
// not count, are checked by mesh_export_test.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>

#include "io/mesh_export.h"
#include "io/mesh_readback_support.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

bool has_admesh() { return std::system("command -v admesh >/dev/null 2>&1") == 0; }

// admesh's report on `stl` (all its checks and repairs; the file itself is left as it is).
std::string admesh_report(const std::filesystem::path& stl) {
  const auto out = stl.string() + ".txt";
  const std::string command = "admesh '" + stl.string() + "' >'" + out + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return test::read_bytes(out);
}

// The first number after `label :` in admesh's report (the "Original" column where there are
// two); fails the test if the label is missing.
double field(const std::string& report, const std::string& label) {
  std::smatch m;
  if (!std::regex_search(report, m, std::regex(label + R"(\s*:\s*(-?[0-9.]+))"))) {
    ADD_FAILURE() << "no '" << label << "' in admesh's report:\n" << report;
    return -1;
  }
  return std::stod(m[1]);
}

// All parts: admesh reads every facet and finds none degenerate (the floor is an open surface,
// so unconnected edges are expected here).
void expect_no_degenerate_facet(const test::BuiltExample& example, const test::TempDir& dir) {
  const auto path = dir / (example.name + ".stl");
  const std::string stl = format_stl(test::all_parts(example.model));
  ASSERT_TRUE(test::write_bytes(path, stl));
  const std::string report = admesh_report(path);
  SCOPED_TRACE(example.name + ", all parts\n" + report);
  EXPECT_EQ(field(report, "Number of facets"), double((stl.size() - 84) / 50));
  EXPECT_EQ(field(report, "Degenerate facets"), 0);
}

// The wall solid alone: closed as admesh sees it (no unconnected edge, nothing to weld, fill or
// flip), and the volume it computes is the plan's (admesh sums in float: 1e-5 relative).
void expect_closed_wall_solid(const test::BuiltExample& example, const test::TempDir& dir) {
  const auto path = dir / (example.name + ".walls.stl");
  ASSERT_TRUE(
      test::write_bytes(path, format_stl({{&example.model.walls}, &example.model.objects})));
  const std::string report = admesh_report(path);
  SCOPED_TRACE(example.name + ", walls\n" + report);
  EXPECT_EQ(field(report, "Degenerate facets"), 0);
  EXPECT_EQ(field(report, "Total disconnected facets"), 0);
  for (const char* repair :
       {"Edges fixed", "Facets removed", "Facets added", "Facets reversed", "Backwards edges"})
    EXPECT_EQ(field(report, repair), 0) << repair;
  EXPECT_NEAR(field(report, "Volume"), example.analytic_volume, 1e-5 * example.analytic_volume);
}

// One test: building the examples takes seconds, once per process.
TEST(StlAdmesh, SeesNoDegenerateFacetAndAClosedWallSolid) {
  ASSERT_TRUE(has_admesh()) << "admesh is not installed: run scripts/setup.sh";
  test::TempDir dir;
  for (const auto& example : test::built_examples()) {
    expect_no_degenerate_facet(example, dir);
    expect_closed_wall_solid(example, dir);
  }
}

}  // namespace
}  // namespace roomcad
