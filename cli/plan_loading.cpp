// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/plan_loading.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

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

}  // namespace

Result<LoadedPlan> load_plan(std::string_view command, const std::filesystem::path& path) {
  Result<std::string> text = read_text_file(path);
  if (!text) {
    report_failure(command, text.error());
    return text.error();
  }
  LoadedPlan loaded{.plan = {}, .text = std::move(text).value(), .report = {}};
  Result<Plan> read = read_plan_text(loaded.text, path.string(), &loaded.report);
  std::fputs(format_report_text(loaded.report, use_colour(stderr)).c_str(), stderr);
  if (!read) {
    std::fprintf(stderr, "%s: %s\n", path.string().c_str(),
                 format_report_summary(loaded.report).c_str());
    return Error{read.code(), read.message()};
  }
  loaded.plan = std::move(read).value();
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
                                   bool force) {
  Result<LoadedPlan> loaded = load_plan(command, path);
  if (!loaded) return loaded;
  ValidateOptions options;
  options.unknown_field_warnings = false;  // the reader has reported them, with positions
  const Report checks = validate(loaded->plan, options);
  std::fputs(format_report_text(checks, use_colour(stderr)).c_str(), stderr);
  loaded->report.append(checks);
  if (checks.ok()) return loaded;
  std::fprintf(stderr, "%s: %s%s\n", path.string().c_str(),
               format_report_summary(loaded->report).c_str(),
               force ? " (going on: --force)" : "; fix them, or pass --force to go on anyway");
  if (!force) return first_error(checks, path);
  return loaded;
}

}  // namespace roomcad::cli
