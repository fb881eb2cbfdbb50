// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad report PLAN -o report.html [--rules R] [--baseline OLD] [--level ID]
// [--picture on|off] [--repair]`: the plan's findings as one self-contained HTML page
// (io/report_page.h).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_checking.h"
#include "io/atomic_write.h"
#include "io/report_page.h"
#include "io/rule_set_file.h"
#include "repair/repair.h"
#include "validation/report_diff.h"

namespace roomcad::cli {
namespace {

struct ReportCommandOptions {
  std::string plan;
  std::string output;
  std::string rules = "default";
  std::string baseline;
  std::string level;
  std::string picture = "on";
  bool repair = false;
};

/// The edits `roomcad repair` (default tolerance) would make, as the page lists them.
std::vector<ReportPageEdit> repair_edits(const Plan& plan) {
  const Result<RepairResult> repaired = repair_plan(plan);
  std::vector<ReportPageEdit> edits;
  if (!repaired) return edits;
  for (const RepairEdit& e : repaired.value().edits) {
    ReportPageEdit edit{{e.object}, {}};
    for (const FindingKey& f : e.clears)
      for (const std::string& o : f.objects)
        if (std::find(edit.objects.begin(), edit.objects.end(), o) == edit.objects.end())
          edit.objects.push_back(o);
    edit.text = fmt::format("{} '{}': clears {} finding{}, moves the solid by at most {:.1f} mm",
                            to_string(e.change), e.object, e.clears.size(),
                            e.clears.size() == 1 ? "" : "s", e.moves * 1000.0);
    edits.push_back(std::move(edit));
  }
  return edits;
}

int run_report(const ReportCommandOptions& options) {
  const Result<RuleSet> rules = load_rule_set(options.rules, "--rules");
  if (!rules) return report_failure("report", rules.error());
  const Result<CheckedPlan> checked = check_plan_file(options.plan, rules.value());
  if (!checked) return report_failure("report", checked.error());
  const CheckedPlan& current = checked.value();
  if (!current.plan) return report_failure("report", not_a_plan(current, options.plan));
  const Plan& plan = *current.plan;
  if (!options.level.empty() && std::none_of(plan.levels.begin(), plan.levels.end(),
                                             [&](const Level& l) { return l.id == options.level; }))
    return report_failure(
        "report", Error{Code::usage_error,
                        fmt::format("--level: {} has no level '{}'", options.plan, options.level)});
  std::optional<ReportComparison> comparison;
  if (!options.baseline.empty()) {
    const Result<CheckedPlan> old = check_plan_file(options.baseline, rules.value());
    if (!old) return report_failure("report", old.error());
    comparison = compare_reports(old.value().report, current.report);
  }
  ReportPageInput page{.title = options.plan,
                       .plan = &plan,
                       .report = &current.report,
                       .item_levels = &current.levels,
                       .comparison = comparison ? &*comparison : nullptr,
                       .baseline_file = options.baseline,
                       .level = options.level,
                       .picture_png = {},
                       .edits = {},
                       .repaired = false};
  if (options.picture == "on") page.picture_png = render_picture_png(plan);
  if (options.repair) {
    page.edits = repair_edits(plan);
    page.repaired = true;
  }
  if (const Status written = write_file_atomically(options.output, make_report_page(page));
      !written)
    return report_failure("report", written.error());
  std::fprintf(stderr, "roomcad report: wrote %s (%zu errors, %zu warnings)\n",
               options.output.c_str(), current.report.error_count(),
               current.report.warning_count());
  return current.report.ok() ? kExitOk : kExitPlanErrors;
}

}  // namespace

void add_report_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<ReportCommandOptions>();
  CLI::App* app = root.add_subcommand(
      "report",
      "Write a plan's findings as one HTML page that opens from disk in any browser, with\n"
      "nothing fetched: a summary by code and level, a floor plan per level whose walls,\n"
      "openings, slabs and rooms carry their ids, and the findings list. Selecting a finding\n"
      "(click, or the arrow keys) marks its objects on the plans and zooms to its place; the\n"
      "list filters by code, level and severity; a link to PAGE#finding-12 opens on that\n"
      "finding. --baseline marks each finding new or unchanged and lists the fixed ones.");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  app->add_option("-o,--output", options->output, "the page to write (HTML)")
      ->required()
      ->type_name("FILE");
  app->add_option("--rules", options->rules,
                  "rule set: default (the format's checks), accessibility, all, or a rules file")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  app->add_option("--baseline", options->baseline,
                  "an earlier revision of the plan to compare with")
      ->type_name("OLD");
  app->add_option("--level", options->level, "only this level's plan and findings")
      ->type_name("ID");
  app->add_option("--picture", options->picture,
                  "a rendered picture of the model in the page (off: quicker on large plans)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app->add_flag("--repair", options->repair,
                "list the edits `roomcad repair` would make (default tolerance), each selectable "
                "on the plans like a finding");
  app->footer(
      "Exit status: 0 written, the plan has no errors; 1 written, the plan has errors; 2 could\n"
      "not run (bad arguments, PLAN or OLD unreadable, an unknown level, the page unwritable).\n"
      "Examples:\n"
      "  roomcad report examples/house.json -o house.html\n"
      "  roomcad report plan.json -o plan.html --rules all --baseline old.json");
  commands.push_back({app, [options] { return run_report(*options); }});
}

}  // namespace roomcad::cli
