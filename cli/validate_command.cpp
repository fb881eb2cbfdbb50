// `roomcad validate PLAN [--format text|json]`: every problem of a plan, in one run.
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/plan_check.h"
#include "io/text_file.h"
#include "validation/report_format.h"

namespace roomcad::cli {
namespace {

struct ValidateCommandOptions {
  std::string plan;
  std::string format = "text";
};

int run_validate(const ValidateCommandOptions& options) {
  const Result<std::string> text = read_text_file(options.plan);
  if (!text) return report_failure("validate", text.error());
  const Report report = check_plan_text(text.value(), options.plan);
  std::string out;
  if (options.format == "json") {
    out = format_report_json(report);
  } else {
    out = format_report_text(report, use_colour(stdout));
    out += options.plan + ": " + format_report_summary(report) + '\n';
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
      "spec's {\"ok\", \"errors\", \"warnings\"} object. Colour only on a terminal.");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  add_format_option(*app, options->format);
  app->footer(
      "Exit status: 0 no errors (warnings allowed); 1 the plan has errors; 2 could not run\n"
      "(bad arguments, PLAN unreadable).\n"
      "Examples:\n"
      "  roomcad validate examples/house.json\n"
      "  roomcad validate --format json plan.json");
  commands.push_back({app, [options] { return run_validate(*options); }});
}

}  // namespace roomcad::cli
