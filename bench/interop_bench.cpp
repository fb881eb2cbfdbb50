// SPDX-License-Identifier: GPL-3.0-or-later
// IFC in and out (issue 18): exporting the 70 x 70 grid (9,940 walls; target under 1 s) and
// importing each bundled IFC model, examples/ifc (target under 0.5 s each; for comparison,
// IFClite opens the 2.5 MB FZK-Haus in about 0.25 s).
#include <filesystem>
#include <fstream>
#include <sstream>

#include <benchmark/benchmark.h>

#include "import/ifc_import.h"
#include "io/ifc_export.h"
#include "testing/grid_plan.h"

namespace {

void BM_IfcExportGrid70(benchmark::State& state) {
  const roomcad::Plan plan = roomcad::samples::make_grid_plan({.n = 70});
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto ifc = roomcad::format_ifc(plan, "grid.ifc");
    if (!ifc.ok()) state.SkipWithError(ifc.error().message.c_str());
    bytes = ifc.value().size();
    benchmark::DoNotOptimize(ifc);
  }
  state.counters["walls"] = static_cast<double>(plan.walls.size());
  state.counters["MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_IfcExportGrid70)->Unit(benchmark::kMillisecond);

void BM_IfcImport(benchmark::State& state, const char* name) {
  std::ifstream in(std::filesystem::path(ROOMCAD_SOURCE_DIR) / "examples" / "ifc" / name,
                   std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string ifc = text.str();
  for (auto _ : state) {
    auto imported = roomcad::import_ifc_text(ifc, name);
    if (!imported.ok()) state.SkipWithError(imported.error().message.c_str());
    benchmark::DoNotOptimize(imported);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * ifc.size()));
}
BENCHMARK_CAPTURE(BM_IfcImport, open_house, "IfcOpenHouse_IFC4.ifc")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IfcImport, duplex, "duplex.ifc")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_IfcImport, sample_project, "tested_sample_project.ifc")
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
