#include "cli/plan_loading.h"

#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "cli/command.h"
#include <fmt/format.h>

#include "io/plan_json.h"
#include "modeling/plan_chords.h"
#include "modeling/plan_levels.h"
#include "io/text_file.h"
#include "validation/report_format.h"
#include "validation/validate.h"

namespace roomcad::cli {

bool use_colour(std::FILE* stream) {
  const char* no_colour = std::getenv("NO_COLOR");
  return (no_colour == nullptr || *no_colour == '\0') && ::isatty(::fileno(stream)) == 1;
}

LoadedPlan load_plan(std::string_view command, const std::filesystem::path& path) {
  LoadedPlan loaded;
  Result<std::string> text = read_text_file(path);
  if (!text) {
    loaded.exit_status = report_failure(command, text.error());
    return loaded;
  }
  loaded.text = std::move(text).value();
  Result<Plan> read = read_plan_text(loaded.text, path.string(), &loaded.report);
  std::fputs(format_report_text(loaded.report, use_colour(stderr)).c_str(), stderr);
  if (!read) {
    std::fprintf(stderr, "%s: %s\n", path.string().c_str(),
                 format_report_summary(loaded.report).c_str());
    loaded.exit_status = kExitPlanErrors;
    return loaded;
  }
  loaded.plan = std::move(read).value();
  return loaded;
}

LoadedPlan load_valid_plan(std::string_view command, const std::filesystem::path& path,
                           bool force) {
  LoadedPlan loaded = load_plan(command, path);
  if (!loaded.plan) return loaded;
  ValidateOptions options;
  options.unknown_field_warnings = false;  // the reader has reported them, with positions
  const Report checks = validate(*loaded.plan, options);
  std::fputs(format_report_text(checks, use_colour(stderr)).c_str(), stderr);
  loaded.report.append(checks);
  if (checks.ok()) return loaded;
  std::fprintf(stderr, "%s: %s%s\n", path.string().c_str(), format_report_summary(loaded.report).c_str(),
               force ? " (going on: --force)" : "; fix them, or pass --force to go on anyway");
  if (!force) {
    loaded.plan.reset();
    loaded.exit_status = kExitPlanErrors;
  }
  return loaded;
}

Result<Plan> select_level(const Plan& plan, const std::string& level) {
  if (level.empty()) return plan;
  if (find_level(plan, level)) return plan_of_level(plan, level);
  std::string known;
  for (const Level& l : plan.levels) known += fmt::format("{}'{}'", known.empty() ? "" : ", ", l.id);
  return Result<Plan>::failure(
      Code::usage_error,
      fmt::format("--level '{}': the plan has no such level (its levels: {})", level,
                  known.empty() ? "none" : known));
}

Plan floor_plan_input(const Plan& plan, bool on_level) {
  Plan heights = plan;
  if (on_level) {
    for (Wall& w : heights.walls) w.level.clear();  // bases stay measured from its floor
    for (Slab& s : heights.slabs) s.level.clear();
  } else {
    heights = with_absolute_heights(std::move(heights));
  }
  return with_arcs_as_chords(heights).plan;
}

}  // namespace roomcad::cli
