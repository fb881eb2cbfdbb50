// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad validate PLAN [--format text|json] [--rules NAME|FILE] [--baseline OLD]
// [--max-findings N] [--format bcf -o FILE]`: every problem of a plan, in one run; with rules
// beyond the format's checks, and compared with an earlier revision.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_checking.h"
#include "cli/plan_loading.h"
#include "io/atomic_write.h"
#include "io/bcf_export.h"
#include "io/rule_set_file.h"
#include "validation/report_diff.h"
#include "validation/report_format.h"

namespace roomcad::cli {
namespace {

struct ValidateCommandOptions {
  std::string plan;
  std::string format = "text";
  std::string rules = "default";
  std::string baseline;
  std::size_t max_findings = 0;  ///< 0: all
  std::string output;            ///< --format bcf: the .bcfzip to write
};

/// Writes the findings as BCF (io/bcf_export.h) to `options.output`.
int write_bcf(const ValidateCommandOptions& options, const CheckedPlan& checked,
              const ReportComparison* comparison) {
  if (!checked.plan)
    return report_failure("validate", not_a_plan(checked, options.plan, "--format bcf: "));
  const Result<std::string> archive = write_bcf_archive({.plan = &*checked.plan,
                                                         .report = &checked.report,
                                                         .comparison = comparison,
                                                         .plan_file = options.plan,
                                                         .date = file_date_for_bcf(options.plan)});
  if (!archive) return report_failure("validate", archive.error());
  if (const Status written = write_file_atomically(options.output, archive.value()); !written)
    return report_failure("validate", written.error());
  std::fprintf(stderr, "roomcad validate: wrote %s (%zu topics)\n", options.output.c_str(),
               checked.report.items.size() + (comparison ? comparison->fixed.items.size() : 0));
  return checked.report.ok() ? kExitOk : kExitPlanErrors;
}

int run_validate(const ValidateCommandOptions& options) {
  const Result<RuleSet> rules = load_rule_set(options.rules, "--rules");
  if (!rules) return report_failure("validate", rules.error());
  if ((options.format == "bcf") != !options.output.empty())
    return report_failure("validate", Error{Code::usage_error,
                                            "-o,--output: give it with --format bcf, and only "
                                            "then (text and JSON go to the standard output)"});
  Result<CheckedPlan> checked = check_plan_file(options.plan, rules.value());
  if (!checked) return report_failure("validate", checked.error());
  if (options.format != "bcf") checked.value().plan.reset();  // its memory serves the printing
  const Report& report = checked.value().report;
  std::optional<ReportComparison> comparison;
  ReportFormatOptions format;
  format.plan_file = options.plan;
  format.ids = rules.value().any_enabled();
  format.item_levels = &checked.value().levels;
  if (options.max_findings > 0) format.max_items = options.max_findings;
  if (!options.baseline.empty()) {
    const Result<CheckedPlan> old = check_plan_file(options.baseline, rules.value());
    if (!old) return report_failure("validate", old.error());
    comparison = compare_reports(old.value().report, report);
    format.comparison = &*comparison;
    format.baseline_file = options.baseline;
  }
  if (options.format == "bcf") return write_bcf(options, checked.value(), format.comparison);
  std::string out;
  if (options.format == "json") {
    out = format_report_json(report, format);
  } else {
    out = format_report_text(report, use_colour(stdout), format);
    out += options.plan + ": " + format_report_summary(report, format) + '\n';
  }
  std::fputs(out.c_str(), stdout);
  if (std::fflush(stdout) != 0) return kExitCannotRun;
  return report.ok() ? kExitOk : kExitPlanErrors;
}

}  // namespace

void add_validate_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<ValidateCommandOptions>();
  CLI::App* app = root.add_subcommand(
      "validate",
      "Check a plan and print every problem in one run: errors (invalid values, duplicate ids,\n"
      "unknown walls, overlapping walls, openings outside their wall, overlapping or blocked\n"
      "openings, anything outside the site) and warnings (unknown fields, raised doors, rooms\n"
      "without a door or a window). Verdicts are exact for the numbers as written; touching\n"
      "is never overlapping. Text names the objects, the place and a concrete fix; JSON is the\n"
      "spec's {\"ok\", \"errors\", \"warnings\"} object. Colour only on a terminal.\n"
      "--rules adds rule sets: door swings, clear space at doors, door and passage widths,\n"
      "turning circles, reachable rooms, escape distances, window sills, duplicates (warnings\n"
      "unless a rules file says \"error\"); each finding's fix is also given as edit commands.\n"
      "--baseline compares with an earlier revision: each item is new or unchanged, and the\n"
      "baseline's items that are gone are listed as fixed.");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  app->add_option("--format", options->format,
                  "text (default), json, or bcf: BCF 2.1 for BIM tools, written to -o")
      ->check(CLI::IsMember({"text", "json", "bcf"}))
      ->capture_default_str();
  app->add_option("-o,--output", options->output,
                  "with --format bcf: the .bcfzip to write (one topic per finding, its objects "
                  "named by the GlobalIds of `roomcad build -o x.ifc`)")
      ->type_name("FILE");
  app->add_option(
         "--rules", options->rules,
         "rule set: default (the format's checks), accessibility, all, or a rules file (JSON)")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  app->add_option("--baseline", options->baseline,
                  "an earlier revision of the plan to compare with")
      ->type_name("OLD");
  app->add_option("--max-findings", options->max_findings,
                  "text: print the first N findings in full and count the rest (0, the "
                  "default: all); a report of 10 findings or more ends with a summary by code "
                  "and level either way")
      ->type_name("N")
      ->check(CLI::NonNegativeNumber);
  app->footer(
      "Exit status: 0 no errors (warnings allowed); 1 the plan has errors; 2 could not run\n"
      "(bad arguments, PLAN, OLD or the rules file unreadable, an unknown rule or a bad\n"
      "threshold).\n"
      "Examples:\n"
      "  roomcad validate examples/house.json\n"
      "  roomcad validate --format json plan.json\n"
      "  roomcad validate plan.json --rules all\n"
      "  roomcad validate plan.json --format bcf -o findings.bcfzip\n"
      "  roomcad validate plan.json --rules examples/rules/accessible-ground-floor.json --baseline "
      "old.json");
  commands.push_back({app, [options] { return run_validate(*options); }});
}

}  // namespace roomcad::cli
