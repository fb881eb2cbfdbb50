// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad fmt PLAN [-o OUT] [--check]`: rewrites a plan in the canonical form.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/plan_json.h"

namespace roomcad::cli {
namespace {

struct FmtOptions {
  std::vector<std::string> plans;
  std::string out;
  bool check = false;
  double wait_seconds = 0.0;
};

int format_one(const FmtOptions& options, const std::string& plan) {
  std::optional<PlanLock> lock;  // rewriting in place: held from reading to the rename
  const bool in_place = !options.check && options.out.empty();
  if (in_place) {
    Result<PlanLock> taken = lock_plan("fmt", plan, options.wait_seconds);
    if (!taken) return exit_status_of(taken.code());
    lock.emplace(std::move(taken).value());
  }
  Result<LoadedPlan> loaded = load_plan("fmt", plan);
  if (!loaded) return exit_status_of(loaded.code());
  const std::string canonical = write_plan_text(loaded->plan);

  if (options.check) {
    if (canonical == loaded->text) return kExitOk;
    std::fprintf(stderr, "%s: not in canonical form; run `roomcad fmt %s` to rewrite it\n",
                 plan.c_str(), plan.c_str());
    return kExitPlanErrors;
  }
  if (options.out == "-") {
    std::fwrite(canonical.data(), 1, canonical.size(), stdout);
    return std::fflush(stdout) == 0 ? kExitOk : kExitCannotRun;
  }
  const std::string& target = options.out.empty() ? plan : options.out;
  if (options.out.empty() && canonical == loaded->text) return kExitOk;  // already canonical
  if (const Status written = write_plan_file(loaded->plan, target); !written)
    return report_failure("fmt", written.error());
  return kExitOk;
}

int run_fmt(const FmtOptions& options) {
  if (!options.out.empty() && options.plans.size() != 1)
    return report_failure("fmt", {Code::usage_error, "-o/--output takes exactly one PLAN"});
  int status = kExitOk;
  for (const std::string& plan : options.plans)
    status = std::max(status, format_one(options, plan));
  return status;
}

}  // namespace

void add_fmt_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<FmtOptions>();
  CLI::App* app = root.add_subcommand(
      "fmt",
      "Rewrite a plan in canonical form: keys in the format's order, every field written with\n"
      "its value (defaults filled in), lengths in metres (a file in \"cm\" or \"mm\" is\n"
      "converted), numbers as the shortest decimal that reads back to the same value, one wall,\n"
      "opening, light or camera per line. Unknown fields are kept (and warned about). The file\n"
      "is replaced atomically: if anything fails, the old file is left as it was. A file already\n"
      "in canonical form is left untouched. Rewriting in place holds the plan's lock, as the\n"
      "edit commands do, so no concurrent edit is lost.");
  app->add_option("PLAN", options->plans, "the plan files (JSON) to format, one or more")
      ->required()
      ->type_name("FILE");
  CLI::Option* out = app->add_option(
      "-o,--output", options->out,
      "write the canonical plan to FILE instead of rewriting PLAN in place (`-` for stdout)");
  out->type_name("FILE");
  app->add_flag("--check", options->check,
                "write nothing; exit 1 if PLAN is not already in canonical form")
      ->excludes(out);
  add_wait_option(*app, options->wait_seconds);
  app->footer(
      "Exit status (the worst over all PLANs): 0 done (with --check: every PLAN is canonical);\n"
      "1 a PLAN has errors (printed to stderr) or, with --check, is not canonical; 2 could not\n"
      "run (bad arguments, a PLAN unreadable, the output not writable).\n"
      "Examples:\n"
      "  roomcad fmt examples/house.json\n"
      "  roomcad fmt draft.json -o clean.json\n"
      "  roomcad fmt --check examples/*.json");
  commands.push_back({app, [options] { return run_fmt(*options); }});
}

}  // namespace roomcad::cli
