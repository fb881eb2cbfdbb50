// SPDX-License-Identifier: GPL-3.0-or-later
// Importing the largest Sweet Home 3D example home (3-BedroomHouseWithMezzanine, 113 kB,
// 67 walls, 37 doors and windows): parsing, junctions, host walls. Target: well under 50 ms,
// so that importing never dominates import + validate + build + render.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <benchmark/benchmark.h>

#include "import/sweethome3d_import.h"

namespace {

std::string read_home() {
  const std::filesystem::path home = std::filesystem::path(ROOMCAD_SOURCE_DIR) / "examples" /
                                     "sweethome3d" / "homes" / "eteks-example-homes" /
                                     "3-BedroomHouseWithMezzanine.Home.xml";
  std::ifstream in(home, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void BM_ImportMezzanineHouse(benchmark::State& state) {
  const std::string xml = read_home();
  for (auto _ : state) {
    auto imported = roomcad::import_sweethome3d_text(xml, "mezzanine");
    if (!imported.ok()) state.SkipWithError(imported.message().c_str());
    benchmark::DoNotOptimize(imported);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * xml.size()));
}
BENCHMARK(BM_ImportMezzanineHouse)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
