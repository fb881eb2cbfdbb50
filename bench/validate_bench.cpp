// Validation time for grids of rooms from about 10 to 100,000 walls (a door in every inner
// wall, three windows in every outer one: about as many openings as walls), printed as a
// markdown table. Run: build/bench/validate_bench [--quick]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>

#include "grid_plan.h"
#include "validation/validate.h"

namespace {

using Clock = std::chrono::steady_clock;

/// CPU time of this thread in milliseconds: on a shared machine, wall-clock time also
/// counts the time other processes hold the cores.
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

struct Timing {
  double wall_ms = 1e300;
  double cpu_ms = 1e300;
  std::size_t errors = 0;
};

/// @return the best of `runs` wall-clock and CPU times of validate(plan), in milliseconds.
Timing time_validate(const roomcad::Plan& plan, const roomcad::ValidateOptions& options, int runs) {
  Timing best;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    const double cpu_start = thread_cpu_ms();
    const roomcad::Report report = roomcad::validate(plan, options);
    best.cpu_ms = std::min(best.cpu_ms, thread_cpu_ms() - cpu_start);
    best.wall_ms = std::min(best.wall_ms, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    best.errors = report.error_count();
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int sides[] = {2, 7, 22, 70, 223};
  std::printf("| grid | walls | openings | validate ms (cpu) | without rooms ms (cpu) | errors |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: |\n");
  for (const int n : sides) {
    if (quick && n > 22) break;
    roomcad::bench::GridSpec spec;
    spec.n = n;
    const roomcad::Plan plan = roomcad::bench::make_grid_plan(spec);
    const int runs = plan.walls.size() > 20000 ? 3 : 10;
    roomcad::ValidateOptions no_rooms;
    no_rooms.room_warnings = false;
    const Timing all = time_validate(plan, {}, runs);
    const Timing without = time_validate(plan, no_rooms, runs);
    std::printf("| %d x %d | %zu | %zu | %.1f (%.1f) | %.1f (%.1f) | %zu |\n", n, n,
                plan.walls.size(), plan.openings.size(), all.wall_ms, all.cpu_ms, without.wall_ms,
                without.cpu_ms, all.errors + without.errors);
  }
  return 0;
}
