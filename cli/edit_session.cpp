// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/edit_session.h"

#include <fmt/format.h>

#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "cli/command.h"
#include "cli/line_diff.h"
#include "cli/plan_loading.h"
#include "io/plan_json.h"
#include "plan/value_text.h"
#include "solid/build_model.h"
#include "validation/report_diff.h"
#include "validation/report_format.h"
#include "validation/validate.h"

namespace roomcad::cli {
namespace {

void print_report(const Report& report) {
  std::fputs(format_report_text(report, use_colour(stderr)).c_str(), stderr);
}

/// Prints "+ id" / "- id" / "~ id" lines, one per object added, removed, changed.
void print_summary(const EditSummary& summary) {
  for (const std::string& id : summary.added) fmt::print("+ {}\n", id);
  for (const std::string& id : summary.removed) fmt::print("- {}\n", id);
  for (const std::string& id : summary.changed) fmt::print("~ {}\n", id);
}

/// Refuses (exit 1) or, with --force, warns about errors the edit introduces.
/// @return true if the edit may go on.
bool accept_new_errors(std::string_view command, const std::string& path, const EditFlags& flags,
                       const Report& fresh) {
  if (fresh.ok()) return true;
  if (flags.force)
    fmt::print(stderr, "roomcad {}: warning: the edit introduces {} (kept: --force)\n", command,
               format_report_summary(fresh));
  else
    fmt::print(stderr,
               "roomcad {}: refused: the edit introduces {}; '{}' is left as it was "
               "(--force writes it anyway)\n",
               command, format_report_summary(fresh), path);
  print_report(fresh);
  return flags.force;
}

/// Prints why an edit was not made. @return its exit status: 1 refused, 2 cannot be made.
int report_not_made(std::string_view command, std::string_view path, const Error& error) {
  if (error.code == Code::edit_refused) {
    fmt::print(stderr, "roomcad {}: refused: {}; '{}' is left as it was\n", command, error.message,
               path);
    return kExitPlanErrors;
  }
  std::string_view message = error.message;  // "<command>: ...", as the edits name their verb
  if (message.starts_with(command) && message.substr(command.size()).starts_with(": "))
    message.remove_prefix(command.size() + 2);
  fmt::print(stderr, "roomcad {}: error: {}\n", command, message);
  return kExitCannotRun;
}

}  // namespace

void add_edit_flags(CLI::App& command, EditFlags& flags) {
  command.add_flag("--force", flags.force,
                   "write the edit even if it introduces plan errors (they are printed)");
  command.add_flag(
      "--dry-run", flags.dry_run,
      "print what would change (objects, then a line diff of the file), write nothing");
  add_wait_option(command, flags.wait_seconds);
  add_verbose_flag(command, flags.verbose);
}

int run_edit(std::string_view command, const std::string& path, const EditFlags& flags,
             const Edit& edit) {
  std::optional<PlanLock> lock;  // held until the new file is in place
  if (!flags.dry_run) {
    Result<PlanLock> taken = lock_plan(command, path, flags.wait_seconds);
    if (!taken) return exit_status_of(taken.code());
    lock.emplace(std::move(taken).value());
  }
  const Result<LoadedPlan> read = load_plan(command, path, findings_for(flags.verbose));
  if (!read) return exit_status_of(read.code());
  Plan edited = read->plan;
  const Result<EditSummary> made = make_edit(edit, edited);
  if (!made) return report_not_made(command, path, made.error());
  const EditSummary& summary = made.value();
  if (edited == read->plan) {
    fmt::print("nothing to change: '{}' is left as it was\n", path);
    return kExitOk;
  }
  if (!accept_new_errors(command, path, flags,
                         introduced_errors(validate(read->plan), validate(edited))))
    return kExitPlanErrors;
  print_summary(summary);
  if (flags.dry_run) {
    std::fputs(diff_lines(read->text, write_plan_text(edited)).c_str(),
               stdout);  // the file as it is
    fmt::print("dry run: '{}' not written\n", path);
    return kExitOk;
  }
  if (const Status written = write_plan_file(edited, path); !written)
    return report_failure(command, written.error());
  return kExitOk;
}

Result<Point2> point_option(std::string_view option, const std::string& text) {
  if (const auto p = parse_point2(text)) return *p;
  return Result<Point2>::failure(
      Code::usage_error,
      fmt::format("{} wants a point x,y in metres (e.g. 1.5,2), got '{}'", option, text));
}

Result<double> number_option(std::string_view option, const std::string& text) {
  if (const auto x = parse_number(text)) return *x;
  return Result<double>::failure(Code::usage_error,
                                 fmt::format("{} wants a finite number, got '{}'", option, text));
}

}  // namespace roomcad::cli
