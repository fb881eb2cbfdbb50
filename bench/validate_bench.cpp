// SPDX-License-Identifier: GPL-3.0-or-later
// Validation time for grids of rooms from about 10 to 100,000 walls (a door in every inner
// wall, three windows in every outer one: about as many openings as walls), printed as a
// markdown table. Run: build/bench/validate_bench [--quick]
// Columns: wall-clock time; CPU time of all threads; the critical path (the longer of the
// two threads validate() runs: rooms beside the other checks), which is the wall-clock time
// on two idle cores; and the same without room warnings (one thread). Best of 3 to 10 runs.
// Then `--rules all` (every rule of the rule sets) on grids with an entrance: its critical path
// is the main thread's CPU time or the other threads' together, whichever is longer (an upper
// bound of the wall-clock time on two idle cores); and each rule alone on the 70 x 70 grid.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <map>
#include <string>

#include "testing/grid_plan.h"
#include "validation/validate.h"

namespace {

using Clock = std::chrono::steady_clock;

/// CPU time in milliseconds of this thread or of the whole process: on a shared machine,
/// wall-clock time also counts the time other processes hold the cores.
double cpu_ms(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

struct Timing {
  double wall_ms = 1e300;
  double cpu_ms = 1e300;       ///< all threads
  double critical_ms = 1e300;  ///< the longer of the two threads: wall time on 2 idle cores
  std::size_t errors = 0;
};

/// @return the best of `runs` wall-clock and CPU times of validate(plan), in milliseconds.
Timing time_validate(const roomcad::Plan& plan, const roomcad::ValidateOptions& options, int runs) {
  Timing best;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    const double thread_start = cpu_ms(CLOCK_THREAD_CPUTIME_ID);
    const double process_start = cpu_ms(CLOCK_PROCESS_CPUTIME_ID);
    const roomcad::Report report = roomcad::validate(plan, options);
    const double main_thread = cpu_ms(CLOCK_THREAD_CPUTIME_ID) - thread_start;
    const double all = cpu_ms(CLOCK_PROCESS_CPUTIME_ID) - process_start;
    best.cpu_ms = std::min(best.cpu_ms, all);
    best.critical_ms = std::min(best.critical_ms, std::max(main_thread, all - main_thread));
    best.wall_ms = std::min(
        best.wall_ms, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    best.errors = report.error_count();
  }
  return best;
}

/// @return the entrance grid plan n x n (a door to the outside, so that walks out exist).
roomcad::Plan entrance_grid(int n) {
  roomcad::samples::GridSpec spec;
  spec.n = n;
  spec.entrance = true;
  return roomcad::samples::make_grid_plan(spec);
}

/// @return "code count, ..." of the report's items.
std::string count_codes(const roomcad::Report& report) {
  std::map<std::string, int> counts;
  for (const roomcad::Diagnostic& d : report.items)
    ++counts[std::string(roomcad::to_string(d.code))];
  std::string out;
  for (const auto& [code, count] : counts)
    out += (out.empty() ? "" : ", ") + code + " " + std::to_string(count);
  return out.empty() ? "none" : out;
}

/// The rule sets' cost: `--rules all` on grids with an entrance, findings counted per code.
void print_rules_table(bool quick) {
  std::printf(
      "\n| rules all: grid | walls | openings | wall ms | cpu ms | critical path ms | findings "
      "|\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | --- |\n");
  for (const int n : {7, 22, 70, 223}) {
    if (quick && n > 22) break;
    const roomcad::Plan plan = entrance_grid(n);
    roomcad::ValidateOptions options;
    options.rules = *roomcad::builtin_rule_set("all");
    const Timing t = time_validate(plan, options, n > 100 ? 3 : 5);
    std::printf("| %d x %d | %zu | %zu | %.1f | %.1f | %.1f | %s |\n", n, n, plan.walls.size(),
                plan.openings.size(), t.wall_ms, t.cpu_ms, t.critical_ms,
                count_codes(roomcad::validate(plan, options)).c_str());
    std::fflush(stdout);
  }
}

/// Each rule alone on one grid: its time beyond the format's checks (which it needs), so
/// that a slow rule shows by name.
void print_rule_costs(int n) {
  const roomcad::Plan plan = entrance_grid(n);
  const Timing base = time_validate(plan, {}, 3);
  std::printf(
      "\n| %d x %d grid, one rule | wall ms beyond validate (%.1f ms) | cpu ms beyond (%.1f ms) | "
      "findings |\n",
      n, n, base.wall_ms, base.cpu_ms);
  std::printf("| --- | ---: | ---: | ---: |\n");
  for (const roomcad::Code code : roomcad::kRuleCodes) {
    roomcad::ValidateOptions options;
    options.rules.enabled[*roomcad::rule_index(code)] = true;
    const Timing t = time_validate(plan, options, 3);
    std::printf(
        "| %s | %.1f | %.1f | %zu |\n", std::string(roomcad::to_string(code)).c_str(),
        t.wall_ms - base.wall_ms, t.cpu_ms - base.cpu_ms,
        roomcad::validate(plan, options).items.size() - roomcad::validate(plan).items.size());
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int sides[] = {2, 7, 22, 70, 223};
  std::printf(
      "| grid | walls | openings | wall ms | cpu ms | critical path ms | no rooms: wall ms | "
      "no rooms: cpu ms | errors |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const int n : sides) {
    if (quick && n > 22) break;
    roomcad::samples::GridSpec spec;
    spec.n = n;
    const roomcad::Plan plan = roomcad::samples::make_grid_plan(spec);
    const int runs = plan.walls.size() > 20000 ? 3 : 10;
    roomcad::ValidateOptions no_rooms;
    no_rooms.room_warnings = false;
    const Timing all = time_validate(plan, {}, runs);
    const Timing without = time_validate(plan, no_rooms, runs);
    std::printf("| %d x %d | %zu | %zu | %.1f | %.1f | %.1f | %.1f | %.1f | %zu |\n", n, n,
                plan.walls.size(), plan.openings.size(), all.wall_ms, all.cpu_ms, all.critical_ms,
                without.wall_ms, without.cpu_ms, all.errors + without.errors);
  }
  print_rules_table(quick);
  print_rule_costs(quick ? 22 : 70);
  return 0;
}
