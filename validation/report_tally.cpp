// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/report_tally.h"

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

namespace roomcad {
namespace {

std::string counted(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

void print(std::string& out, std::string_view heading, const std::vector<FindingCount>& counts) {
  std::size_t width = 0;
  for (const FindingCount& c : counts) width = std::max(width, c.name.size());
  out += fmt::format("{}\n", heading);
  for (const FindingCount& c : counts) {
    std::string both;
    if (c.errors) both = counted(c.errors, "error");
    if (c.warnings) both += (both.empty() ? "" : ", ") + counted(c.warnings, "warning");
    out += fmt::format("  {:<{}}  {}\n", c.name, width, both);
  }
}

}  // namespace

void count_finding(std::vector<FindingCount>& counts, std::string_view name,
                   const Diagnostic& item) {
  auto it = std::find_if(counts.begin(), counts.end(),
                         [&](const FindingCount& c) { return c.name == name; });
  if (it == counts.end()) it = counts.insert(counts.end(), FindingCount{std::string(name)});
  ++(item.severity == Severity::error ? it->errors : it->warnings);
}

std::vector<std::string> item_levels(const Report& report, const Plan& plan) {
  if (plan.levels.empty()) return std::vector<std::string>(report.items.size());  // none
  std::unordered_map<std::string_view, std::string_view> level_of;
  level_of.reserve(plan.walls.size() + plan.slabs.size() + plan.openings.size());
  for (const Wall& w : plan.walls) level_of.emplace(w.id, w.level);
  for (const Slab& s : plan.slabs) level_of.emplace(s.id, s.level);
  for (const Opening& o : plan.openings)
    if (const auto host = level_of.find(o.wall); host != level_of.end())
      level_of.emplace(o.id, host->second);
  std::vector<std::string> levels;
  levels.reserve(report.items.size());
  for (const Diagnostic& d : report.items) {
    std::string_view level;
    for (const std::string& id : d.objects)
      if (const auto it = level_of.find(id); it != level_of.end() && !it->second.empty()) {
        level = it->second;
        break;
      }
    levels.emplace_back(level);
  }
  return levels;
}

std::string format_report_tally(const Report& report, const std::vector<std::string>& levels) {
  std::vector<FindingCount> by_code, by_level;
  for (std::size_t i = 0; i < report.items.size(); ++i) {
    const Diagnostic& d = report.items[i];
    count_finding(by_code, to_string(d.code), d);
    if (!levels.empty()) count_finding(by_level, levels[i].empty() ? "(no level)" : levels[i], d);
  }
  std::string out;
  print(out, "by code:", by_code);
  const bool any_level =
      std::any_of(levels.begin(), levels.end(), [](const std::string& l) { return !l.empty(); });
  if (any_level) print(out, "by level:", by_level);
  return out;
}

}  // namespace roomcad
