#include "cli/plan_loading.h"

#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#include "cli/command.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "validation/report_format.h"

namespace roomcad::cli {

bool use_colour(std::FILE* stream) {
  const char* no_colour = std::getenv("NO_COLOR");
  return (no_colour == nullptr || *no_colour == '\0') && ::isatty(::fileno(stream)) == 1;
}

LoadedPlan load_plan(std::string_view command, const std::filesystem::path& path) {
  LoadedPlan loaded;
  Result<std::string> text = read_text_file(path);
  if (!text.ok()) {
    std::fprintf(stderr, "roomcad %.*s: error: %s\n", static_cast<int>(command.size()),
                 command.data(), text.error().c_str());
    loaded.exit_status = kCannotRun;
    return loaded;
  }
  loaded.text = std::move(text).value();
  PlanReadResult read = read_plan_text(loaded.text, path.string());
  const std::string problems = format_report_text(read.report, use_colour(stderr));
  std::fputs(problems.c_str(), stderr);
  if (!read.plan) {
    std::fprintf(stderr, "%s: %s\n", path.string().c_str(),
                 format_report_summary(read.report).c_str());
    loaded.exit_status = kPlanErrors;
  }
  loaded.plan = std::move(read.plan);
  loaded.report = std::move(read.report);
  return loaded;
}

}  // namespace roomcad::cli
