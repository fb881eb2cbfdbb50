// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/report_diff.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace roomcad {
namespace {

/// An error's identity across an edit.
using ErrorKey = std::pair<Code, std::vector<std::string>>;

ErrorKey key_of(const Diagnostic& d) {
  std::vector<std::string> ids = d.objects;
  std::sort(ids.begin(), ids.end());
  return {d.code, std::move(ids)};
}

}  // namespace

Report introduced_errors(const Report& before, const Report& after) {
  std::map<ErrorKey, int> budget;
  for (const Diagnostic& d : before.items)
    if (d.severity == Severity::error) ++budget[key_of(d)];
  Report fresh;
  for (const Diagnostic& d : after.items) {
    if (d.severity != Severity::error) continue;
    int& left = budget[key_of(d)];
    if (left > 0) --left;
    else fresh.add(d);
  }
  return fresh;
}

std::vector<std::string> item_ids(const Report& report) {
  std::map<std::string, int> seen;
  std::vector<std::string> out;
  for (const Diagnostic& d : report.items) {
    std::vector<std::string> ids = d.objects;
    std::sort(ids.begin(), ids.end());
    std::string id = std::string(to_string(d.code)) + ':';
    for (std::size_t i = 0; i < ids.size(); ++i) id += (i ? "+" : "") + ids[i];
    if (ids.empty())
      id += d.location && !d.location->pointer.empty() ? d.location->pointer : d.message;
    const int repeat = ++seen[id];
    out.push_back(repeat == 1 ? id : id + '#' + std::to_string(repeat));
  }
  return out;
}

std::string_view to_string(ItemStatus status) {
  return status == ItemStatus::added ? "new" : "unchanged";
}

ReportComparison compare_reports(const Report& baseline, const Report& current) {
  ReportComparison c;
  c.ids = item_ids(current);
  const std::vector<std::string> old_ids = item_ids(baseline);
  std::map<std::string, std::size_t> old_index;
  for (std::size_t i = 0; i < old_ids.size(); ++i) old_index.emplace(old_ids[i], i);
  std::vector<bool> kept(old_ids.size(), false);
  for (const std::string& id : c.ids) {
    const auto it = old_index.find(id);
    c.status.push_back(it == old_index.end() ? ItemStatus::added : ItemStatus::unchanged);
    if (it != old_index.end()) kept[it->second] = true;
  }
  for (std::size_t i = 0; i < old_ids.size(); ++i)
    if (!kept[i]) c.fixed.add(baseline.items[i]), c.fixed_ids.push_back(old_ids[i]);
  return c;
}

}  // namespace roomcad
