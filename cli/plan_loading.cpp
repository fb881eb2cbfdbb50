// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/plan_loading.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <unistd.h>

#include "cli/command.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "validation/report_format.h"
#include "validation/validate.h"

namespace roomcad::cli {

bool use_colour(std::FILE* stream) {
  const char* no_colour = std::getenv("NO_COLOR");
  return (no_colour == nullptr || *no_colour == '\0') && ::isatty(::fileno(stream)) == 1;
}

namespace {

/// The report's first error as the reason a command stops, worded as its summary line.
Error first_error(const Report& report, const std::filesystem::path& path) {
  const auto error =
      std::find_if(report.items.begin(), report.items.end(),
                   [](const Diagnostic& d) { return d.severity == Severity::error; });
  return Error{error == report.items.end() ? Code::invalid_value : error->code,
               fmt::format("{}: {}", path.string(), format_report_summary(report))};
}

/// "wall_overlap, room_without_window": the report's codes, each once, in order.
std::string codes_of(const Report& report) {
  std::vector<std::string_view> codes;
  for (const Diagnostic& d : report.items)
    if (std::find(codes.begin(), codes.end(), to_string(d.code)) == codes.end())
      codes.push_back(to_string(d.code));
  return fmt::format("{}", fmt::join(codes, ", "));
}

/// The one line about a report: its counts (listed: after the findings themselves), or its
/// counts, codes and the command that lists them (counted); then `then`.
void print_summary(const Report& report, const std::filesystem::path& path, Findings findings,
                   std::string_view then) {
  const std::string file = path.string();
  if (findings == Findings::listed)
    std::fprintf(stderr, "%s: %s%.*s\n", file.c_str(), format_report_summary(report).c_str(),
                 int(then.size()), then.data());
  else
    std::fprintf(stderr, "%s: %s (%s): `roomcad validate %s` lists them%.*s\n", file.c_str(),
                 format_report_summary(report).c_str(), codes_of(report).c_str(), file.c_str(),
                 int(then.size()), then.data());
}

void list_findings(const Report& report) {
  std::fputs(format_report_text(report, use_colour(stderr)).c_str(), stderr);
}

/// load_plan, but the counted line of a plan that reads is left to the caller.
Result<LoadedPlan> read_plan(std::string_view command, const std::filesystem::path& path,
                             Findings findings) {
  Result<std::string> text = read_text_file(path);
  if (!text) {
    report_failure(command, text.error());
    return text.error();
  }
  LoadedPlan loaded{.plan = {}, .text = std::move(text).value(), .report = {}};
  Result<Plan> read = read_plan_text(loaded.text, path.string(), &loaded.report);
  if (findings == Findings::listed) list_findings(loaded.report);
  if (!read) {
    print_summary(loaded.report, path, findings, "");
    return Error{read.code(), read.message()};
  }
  loaded.plan = std::move(read).value();
  return loaded;
}

}  // namespace

Result<LoadedPlan> load_plan(std::string_view command, const std::filesystem::path& path,
                             Findings findings) {
  Result<LoadedPlan> loaded = read_plan(command, path, findings);
  if (loaded && findings == Findings::counted && !loaded->report.items.empty())
    print_summary(loaded->report, path, findings, "");
  return loaded;
}

Result<PlanLock> lock_plan(std::string_view command, const std::filesystem::path& path,
                           double wait_seconds) {
  Result<PlanLock> lock =
      PlanLock::acquire(path, wait_duration(wait_seconds), fmt::format("roomcad {}", command));
  if (lock) return lock;
  Error error = lock.error();
  if (error.code == Code::lock_timeout) error.message += "; --wait SECONDS waits longer";
  report_failure(command, error);
  return error;
}

Result<LoadedPlan> load_valid_plan(std::string_view command, const std::filesystem::path& path,
                                   bool force, Findings findings) {
  Result<LoadedPlan> loaded = read_plan(command, path, findings);
  if (!loaded) return loaded;
  ValidateOptions options;
  options.unknown_field_warnings = false;  // the reader has reported them, with positions
  const Report checks = validate(loaded->plan, options);
  if (findings == Findings::listed) list_findings(checks);
  loaded->report.append(checks);
  const std::string_view then = checks.ok() ? ""
                                : force     ? " (going on: --force)"
                                            : "; fix them, or pass --force to go on anyway";
  // Listed, a line only where there are errors (as before); counted, one whenever there is
  // anything to count.
  if (!checks.ok() || (findings == Findings::counted && !loaded->report.items.empty()))
    print_summary(loaded->report, path, findings, then);
  if (!checks.ok() && !force) return first_error(checks, path);
  return loaded;
}

}  // namespace roomcad::cli
