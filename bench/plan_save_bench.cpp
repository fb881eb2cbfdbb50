// SPDX-License-Identifier: GPL-3.0-or-later
// What a durable save costs (bench/report.md, "Edits"): write_plan_file, which flushes the new file
// to disk before renaming it over the plan and the folder after (io/atomic_write.h), against the
// same text written and renamed without the two flushes; the text alone; and the plan lock
// (io/plan_lock.h) taken and released. Grid plans of 112 and 9,940 walls (testing/grid_plan.h,
// n = 7 and 70), written in a fresh folder under the system's temporary folder (its file system
// decides the cost of a flush). Wall-clock time: a flush waits for the disk, not the CPU.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "io/plan_json.h"
#include "io/plan_lock.h"
#include "testing/grid_plan.h"

namespace roomcad {
namespace {

/// A fresh folder, removed at the end of the benchmark.
struct Folder {
  std::filesystem::path path;
  Folder() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "roomcad-save-bench-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();
    path = pattern;
  }
  ~Folder() { std::filesystem::remove_all(path); }
};

Plan grid_of(benchmark::State& state) {
  return samples::make_grid_plan({.n = static_cast<int>(state.range(0))});
}

void BM_SaveDurable(benchmark::State& state) {
  const Plan plan = grid_of(state);
  const Folder folder;
  const auto path = folder.path / "plan.json";
  for (auto _ : state)
    if (!write_plan_file(plan, path)) state.SkipWithError("write failed");
  state.counters["walls"] = static_cast<double>(plan.walls.size());
}
BENCHMARK(BM_SaveDurable)->Arg(7)->Arg(70)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The baseline: the same text to a temporary file, renamed over the plan, nothing flushed.
void BM_SaveWithoutFsync(benchmark::State& state) {
  const Plan plan = grid_of(state);
  const Folder folder;
  const auto path = folder.path / "plan.json";
  const auto temporary = folder.path / ".plan.json.tmp";
  for (auto _ : state) {
    const std::string text = write_plan_text(plan);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const bool written =
        fd >= 0 && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    if (fd >= 0) ::close(fd);
    if (!written || ::rename(temporary.c_str(), path.c_str()) != 0)
      state.SkipWithError("write failed");
  }
  state.counters["walls"] = static_cast<double>(plan.walls.size());
}
BENCHMARK(BM_SaveWithoutFsync)->Arg(7)->Arg(70)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PlanText(benchmark::State& state) {
  const Plan plan = grid_of(state);
  for (auto _ : state) benchmark::DoNotOptimize(write_plan_text(plan));
  state.counters["walls"] = static_cast<double>(plan.walls.size());
}
BENCHMARK(BM_PlanText)->Arg(7)->Arg(70)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LockAndRelease(benchmark::State& state) {
  const Folder folder;
  const auto path = folder.path / "plan.json";
  for (auto _ : state)
    if (!PlanLock::acquire(path, std::chrono::milliseconds(0), "bench"))
      state.SkipWithError("not locked");
}
BENCHMARK(BM_LockAndRelease)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
