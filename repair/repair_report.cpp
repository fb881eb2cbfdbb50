// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair/repair_report.h"

#include <algorithm>
#include <numeric>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "validation/report_format.h"

namespace roomcad {
namespace {

using Json = nlohmann::ordered_json;

Json json_value(const RepairValue& value) {
  return std::visit(
      [](const auto& v) -> Json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Point2>) return Json::array({v.x, v.y});
        else if constexpr (std::is_same_v<T, Polygon>) {
          Json out = Json::array();
          for (const Point2& p : v) out.push_back(Json::array({p.x, p.y}));
          return out;
        } else return v;
      },
      value);
}

Json json_fields(const RepairFields& values) {
  Json out = Json::object();
  for (const auto& [key, value] : values) out[key] = json_value(value);
  return out;
}

Json json_counts(const std::map<Code, std::size_t>& counts) {
  Json out = Json::object();
  for (const auto& [code, n] : counts) out[std::string(to_string(code))] = n;
  return out;
}

Json json_edit(const RepairEdit& e) {
  Json clears = Json::array();
  for (const FindingKey& k : e.clears)
    clears.push_back({{"code", std::string(to_string(k.code))}, {"objects", k.objects}});
  return {{"object", e.object},
          {"change", std::string(to_string(e.change))},
          {"old", json_fields(e.old_values)},
          {"new", e.change == RepairChange::remove ? Json(nullptr) : json_fields(e.new_values)},
          {"clears", clears},
          {"moves", e.moves}};
}

std::string lines(const std::vector<std::string>& items) {
  if (items.empty()) return "[]";
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ",\n    " : "\n    ") + items[i];
  return out + "\n  ]";
}

std::size_t total(const std::map<Code, std::size_t>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0},
                         [](std::size_t n, const auto& c) { return n + c.second; });
}

double largest_move(const RepairResult& r) {
  double most = 0;
  for (const RepairEdit& e : r.edits) most = std::max(most, e.moves);
  return most;
}

/// A length in millimetres as a person reads it: "4 mm", "0.3 mm", "0 mm".
std::string millimetres(double metres) {
  const double mm = metres * 1000;
  if (mm == 0) return "0 mm";
  if (mm < 0.001) return "< 0.001 mm";
  return fmt::format("{:.3g} mm", mm);
}

std::string text_value(const RepairValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Point2>) return fmt::format("({:.4g}, {:.4g})", v.x, v.y);
        else if constexpr (std::is_same_v<T, Polygon>) return fmt::format("{} corners", v.size());
        else if constexpr (std::is_same_v<T, double>) return fmt::format("{:.4g}", v);
        else return v;
      },
      value);
}

std::string text_edit(const RepairEdit& e) {
  std::string out = fmt::format("  {} '{}'", to_string(e.change), e.object);
  std::vector<std::string> changes;
  for (std::size_t i = 0; i < e.new_values.size(); ++i)
    changes.push_back(fmt::format("{} {} -> {}", e.new_values[i].first,
                                  text_value(e.old_values[i].second),
                                  text_value(e.new_values[i].second)));
  if (!changes.empty()) out += ": " + fmt::format("{}", fmt::join(changes, ", "));
  std::set<std::string> codes;
  for (const FindingKey& k : e.clears) codes.insert(std::string(to_string(k.code)));
  if (!e.clears.empty())
    out += fmt::format("; clears {} finding{} ({})", e.clears.size(),
                       e.clears.size() == 1 ? "" : "s", fmt::join(codes, ", "));
  return out + "; moves " + millimetres(e.moves) + '\n';
}

}  // namespace

std::string format_repair_json(const RepairResult& r) {
  std::vector<std::string> edits, remaining;
  for (const RepairEdit& e : r.edits) edits.push_back(json_edit(e).dump());
  for (const RemainingFinding& f : r.remaining) {
    std::string item = format_item_json(f.finding);
    item.pop_back();
    remaining.push_back(item + ", \"reason\": " + Json(f.reason).dump() + '}');
  }
  return fmt::format(
      "{{\n  \"tolerance\": {},\n  \"before\": {},\n  \"after\": {},\n  \"edits\": {},\n"
      "  \"remaining\": {}\n}}\n",
      Json(r.tolerance).dump(), json_counts(r.before).dump(), json_counts(r.after).dump(),
      lines(edits), lines(remaining));
}

std::string format_repair_summary(const RepairResult& r) {
  const std::size_t before = total(r.before), after = total(r.after);
  return fmt::format("{} edit{} clear {} of {} error{}, {} remain{}; the solid moves at most {}",
                     r.edits.size(), r.edits.size() == 1 ? "" : "s",
                     before > after ? before - after : 0, before, before == 1 ? "" : "s", after,
                     after == 1 ? "s" : "", millimetres(largest_move(r)));
}

std::string format_repair_text(const RepairResult& r, bool verbose) {
  constexpr std::size_t kShown = 20;
  std::string out;
  if (!r.edits.empty()) out += "edits:\n";
  const std::size_t shown = verbose ? r.edits.size() : std::min(r.edits.size(), kShown);
  for (std::size_t i = 0; i < shown; ++i) out += text_edit(r.edits[i]);
  if (shown < r.edits.size())
    out += fmt::format("  ... and {} more (--verbose lists them all)\n", r.edits.size() - shown);
  std::set<Code> codes;
  for (const auto& [code, n] : r.before) codes.insert(code);
  for (const auto& [code, n] : r.after) codes.insert(code);
  if (!codes.empty()) out += fmt::format("{:<24}{:>8}{:>8}\n", "errors", "before", "after");
  const auto count = [](const std::map<Code, std::size_t>& m, Code c) {
    const auto it = m.find(c);
    return it == m.end() ? std::size_t{0} : it->second;
  };
  for (const Code c : codes)
    out += fmt::format("  {:<22}{:>8}{:>8}\n", to_string(c), count(r.before, c), count(r.after, c));
  const std::size_t listed = verbose ? r.remaining.size() : std::min(r.remaining.size(), kShown);
  if (!r.remaining.empty()) out += "remaining:\n";
  for (std::size_t i = 0; i < listed; ++i) {
    const RemainingFinding& f = r.remaining[i];
    out += fmt::format("  error[{}] {}: {}\n    left because: {}\n", to_string(f.finding.code),
                       fmt::join(f.finding.objects, ", "), f.finding.message, f.reason);
  }
  if (listed < r.remaining.size())
    out +=
        fmt::format("  ... and {} more (--verbose lists them all)\n", r.remaining.size() - listed);
  return out;
}

}  // namespace roomcad
