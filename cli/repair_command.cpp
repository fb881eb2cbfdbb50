// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad repair PLAN -o OUT [--tolerance T] [--only CODE,...] [--dry-run] [--format text|json]`:
// clears what it can of the plan's errors by edits that move the built solid by at most T.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/atomic_write.h"
#include "io/plan_json.h"
#include "repair/repair.h"
#include "repair/repair_report.h"

namespace roomcad::cli {
namespace {

struct RepairArgs {
  std::string plan;
  std::string out;
  double tolerance = 0.01;
  std::vector<std::string> only;
  bool dry_run = false;
  bool verbose = false;
  std::string format = "text";
  double wait_seconds = 0.0;
};

Result<std::vector<Code>> parse_codes(const std::vector<std::string>& names) {
  std::vector<Code> codes;
  for (const std::string& name : names) {
    const std::optional<Code> code = parse_code(name);
    if (!code)
      return Result<std::vector<Code>>::failure(
          Code::usage_error,
          fmt::format("--only: '{}' is no validation code (wall_overlap, slab_overlap, "
                      "opening_overlap, opening_blocked, opening_outside_wall, ...)",
                      name));
    codes.push_back(*code);
  }
  return codes;
}

int run_repair(const RepairArgs& args) {
  if (!args.dry_run && args.out.empty())
    return report_failure("repair",
                          {Code::usage_error, "-o/--output OUT is required (or --dry-run)"});
  if (!(std::isfinite(args.tolerance) && args.tolerance >= 0))
    return report_failure(
        "repair", {Code::usage_error, fmt::format("--tolerance must be a number of metres >= 0, "
                                                  "not {}",
                                                  args.tolerance)});
  const Result<std::vector<Code>> only = parse_codes(args.only);
  if (!only) return report_failure("repair", only.error());
  std::optional<PlanLock> lock;  // held from reading the plan to writing the repaired one
  if (!args.dry_run) {
    Result<PlanLock> taken = lock_plan("repair", args.plan, args.wait_seconds);
    if (!taken) return exit_status_of(taken.code());
    lock.emplace(std::move(taken).value());
  }
  Result<LoadedPlan> loaded = load_plan("repair", args.plan, Findings::counted);
  if (!loaded) return kExitCannotRun;  // could not run: a file that does not read as a plan
  const Result<RepairResult> repaired =
      repair_plan(loaded->plan, {.tolerance = args.tolerance, .only = *only});
  if (!repaired) return report_failure("repair", repaired.error());
  const RepairResult& r = *repaired;
  if (args.format == "json") {
    const std::string json = format_repair_json(r);
    std::fwrite(json.data(), 1, json.size(), stdout);
  } else {
    std::printf("%s: %s%s\n", args.plan.c_str(), format_repair_summary(r).c_str(),
                args.dry_run ? " (dry run: nothing written)" : "");
    std::fputs(format_repair_text(r, args.verbose).c_str(), stdout);
  }
  if (!args.dry_run) {
    // Nothing to repair: the file's own bytes, so that it comes back byte for byte.
    const std::string text = r.edits.empty() ? loaded->text : write_plan_text(r.plan);
    if (const Status written = write_file_atomically(args.out, text); !written)
      return report_failure("repair", written.error());
  }
  return r.remaining.empty() ? kExitOk : kExitPlanErrors;
}

}  // namespace

void add_repair_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<RepairArgs>();
  CLI::App* app = root.add_subcommand(
      "repair",
      "Clear the drafting noise of a plan: walls drawn twice or over one another, wall ends\n"
      "drawn into their neighbours, slabs drawn over one another, openings overlapping, past\n"
      "their wall or blocked by a wall across their side. Each edit moves the built solid by\n"
      "at most the tolerance, and by nothing where the union of the solids allows: a wall\n"
      "inside another is removed, walls over one another are trimmed to meet, an end inside\n"
      "another wall moves onto its centre line (a T join), openings keep their place in the\n"
      "world and their ids. The repaired plan is written to OUT atomically, under the plan's\n"
      "lock; a plan with nothing to repair is written byte for byte. The report lists every\n"
      "edit (old and new values, the findings it clears, how far the solid can move), the\n"
      "errors before and after, and why each remaining error was left.");
  app->add_option("PLAN", args->plan, "the plan file (JSON)")->required()->type_name("FILE");
  app->add_option("-o,--output", args->out, "the repaired plan to write (may be PLAN itself)")
      ->type_name("OUT");
  app->add_option("--tolerance", args->tolerance,
                  "how far, in metres, the built solid may move (>= 0)")
      ->capture_default_str();
  app->add_option("--only", args->only, "repair only findings of these codes (comma-separated)")
      ->delimiter(',')
      ->type_name("CODE,...");
  app->add_flag("--dry-run", args->dry_run, "report what would be done, write nothing");
  add_format_option(*app, args->format, "report format");
  add_verbose_flag(*app, args->verbose)
      ->description("list every edit and remaining error (without it, the first 20 of each)");
  add_wait_option(*app, args->wait_seconds);
  app->footer(
      "Exit status: 0 no error remains; 1 some remain (listed with why); 2 could not run (bad\n"
      "arguments, PLAN unreadable or not a plan, OUT not writable).\n"
      "Examples:\n"
      "  roomcad repair home.json -o home-repaired.json\n"
      "  roomcad repair home.json --dry-run --format json\n"
      "  roomcad repair home.json -o home.json --only wall_overlap --tolerance 0.005");
  commands.push_back({app, [args] { return run_repair(*args); }});
}

}  // namespace roomcad::cli
