// SPDX-License-Identifier: GPL-3.0-or-later
// Built-in rule sets and the rules file reader.
#include "validation/rule_set.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "plan/nearest_name.h"
#include "validation/detail/habitable_rooms.h"

namespace roomcad {
namespace {

using Json = nlohmann::json;

/// A threshold a rule takes in a rules file: its key and where it is stored.
struct ThresholdKey {
  Code rule;
  std::string_view key;
  double RuleThresholds::*field;
};

constexpr ThresholdKey kThresholdKeys[] = {
    {Code::door_clearance, "width", &RuleThresholds::clearance_width},
    {Code::door_clearance, "depth", &RuleThresholds::clearance_depth},
    {Code::door_too_narrow, "min_width", &RuleThresholds::door_min_width},
    {Code::passage_too_narrow, "min_width", &RuleThresholds::passage_min_width},
    {Code::no_turning_circle, "diameter", &RuleThresholds::turning_diameter},
    {Code::escape_too_far, "max_distance", &RuleThresholds::escape_max_distance},
    {Code::window_sill_low, "min_sill", &RuleThresholds::window_min_sill},
    {Code::window_sill_high, "max_sill", &RuleThresholds::window_max_sill},
};

constexpr std::string_view kTopLevelKeys[] = {"format", "version",          "base",
                                              "rules",  "accessible_rooms", "habitable_rooms"};

/// A failure while reading: the JSON pointer and what is wrong there.
struct Problem {
  std::string pointer;
  std::string what;
};

Error usage_error(const std::string& file, const Problem& p) {
  return {Code::usage_error,
          fmt::format("{}: {}: {}", file, p.pointer.empty() ? "/" : p.pointer, p.what),
          Location{file, p.pointer, 0, 0}};
}

std::string value_text(const Json& v) {
  std::string text = v.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

/// "unknown X \"name\" (did you mean \"near\"?)", or with the list of known names.
std::string unknown_name(std::string_view what, const std::string& name,
                         const std::vector<std::string_view>& known) {
  if (const auto near = nearest_name(name, known))
    return fmt::format("unknown {} \"{}\" (did you mean \"{}\"?)", what, name, *near);
  std::string list;
  for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  return fmt::format("unknown {} \"{}\" (known: {})", what, name, list);
}

std::vector<std::string_view> rule_names() {
  std::vector<std::string_view> names;
  for (const Code c : kRuleCodes) names.push_back(to_string(c));
  return names;
}

std::optional<Problem> read_threshold(const Json& value, const std::string& pointer, double& out) {
  if (!value.is_number() || !std::isfinite(value.get<double>()) || !(value.get<double>() > 0) ||
      value.get<double>() > 1e6)
    return Problem{pointer,
                   fmt::format("expected a positive number of metres (at most 1e6), found {}",
                               value_text(value))};
  out = value.get<double>();
  return std::nullopt;
}

/// A date of the insolation rule: `MM-DD` or `YYYY-MM-DD`.
bool is_rule_date(const Json& v) {
  if (!v.is_string()) return false;
  const std::string s = v.get<std::string>();
  const std::string md = s.size() == 10 ? s.substr(5) : s;
  if (s.size() == 10 && !(std::all_of(s.begin(), s.begin() + 4, ::isdigit) && s[4] == '-'))
    return false;
  if (md.size() != 5 || md[2] != '-' || !std::isdigit(md[0]) || !std::isdigit(md[1]) ||
      !std::isdigit(md[3]) || !std::isdigit(md[4]))
    return false;
  const int month = std::stoi(md.substr(0, 2)), day = std::stoi(md.substr(3));
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month >= 1 && month <= 12 && day >= 1 && day <= kDays[month - 1];
}

std::optional<Problem> read_hours(const Json& value, const std::string& at, double most,
                                  std::string_view unit, double& out) {
  if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0 ||
      value.get<double>() > most)
    return Problem{at, fmt::format("expected a number of {} from 0 to {}, found {}", unit, most,
                                   value_text(value))};
  out = value.get<double>();
  return std::nullopt;
}

/// The settings of insolation_short beyond enabled and severity (InsolationRule).
std::optional<Problem> read_insolation_setting(const std::string& key, const Json& value,
                                               const std::string& at, InsolationRule& rule) {
  if (key == "date" || key == "period") {
    const bool one = key == "date";
    const std::vector<Json> dates =
        one ? std::vector<Json>{value}
            : (value.is_array() && value.size() == 2 ? std::vector<Json>{value[0], value[1]}
                                                     : std::vector<Json>{});
    if (dates.empty() || !std::all_of(dates.begin(), dates.end(), is_rule_date))
      return Problem{at,
                     fmt::format("expected {} (MM-DD or YYYY-MM-DD), found {}",
                                 one ? "a date" : "two dates [first, last]", value_text(value))};
    rule.dates.clear();
    for (const Json& d : dates) rule.dates.push_back(d.get<std::string>());
    return std::nullopt;
  }
  if (key == "min_continuous_hours")
    return read_hours(value, at, 24, "hours", rule.min_continuous_hours);
  if (key == "min_total_hours") {
    double hours = 0;
    if (auto p = read_hours(value, at, 24, "hours", hours)) return p;
    rule.min_total_hours = hours;
    return std::nullopt;
  }
  if (key == "min_period_hours") return read_hours(value, at, 24, "hours", rule.min_period_hours);
  if (key == "ignore_after_sunrise_minutes")
    return read_hours(value, at, 720, "minutes", rule.ignore_after_sunrise_minutes);
  if (key == "ignore_before_sunset_minutes")
    return read_hours(value, at, 720, "minutes", rule.ignore_before_sunset_minutes);
  if (key == "min_area") return read_hours(value, at, 1e6, "square metres", rule.min_area);
  if (key == "above_sill") return read_hours(value, at, 10, "metres", rule.above_sill);
  if (key == "into_reveal") return read_hours(value, at, 10, "metres", rule.into_reveal);
  if (key == "rooms") {
    if (!value.is_string())
      return Problem{at, "expected a regular expression of room names, found " + value_text(value)};
    try {
      (void)std::regex(value.get<std::string>(), std::regex::ECMAScript | std::regex::icase);
    } catch (const std::regex_error& e) {
      return Problem{at,
                     fmt::format("not a regular expression ({}): {}", e.what(), value_text(value))};
    }
    rule.room_pattern = value.get<std::string>();
    return std::nullopt;
  }
  return Problem{at, unknown_name("setting of insolation_short", key,
                                  {"enabled", "severity", "date", "period", "min_continuous_hours",
                                   "min_total_hours", "min_period_hours",
                                   "ignore_after_sunrise_minutes", "ignore_before_sunset_minutes",
                                   "rooms", "min_area", "above_sill", "into_reveal"})};
}

std::optional<Problem> read_rule_object(const Json& body, Code rule, const std::string& pointer,
                                        RuleSet& set) {
  const std::size_t index = *rule_index(rule);
  set.enabled[index] = true;
  for (const auto& [key, value] : body.items()) {
    const std::string at = pointer + '/' + key;
    if (key == "enabled") {
      if (!value.is_boolean())
        return Problem{at, "expected true or false, found " + value_text(value)};
      set.enabled[index] = value.get<bool>();
      continue;
    }
    if (key == "severity") {
      if (value == "warning" || value == "error") {
        set.severity[index] = value == "error" ? Severity::error : Severity::warning;
        continue;
      }
      return Problem{at, "expected \"warning\" or \"error\", found " + value_text(value)};
    }
    if (rule == Code::insolation_short) {
      if (auto p = read_insolation_setting(key, value, at, set.insolation)) return p;
      continue;
    }
    std::vector<std::string_view> known = {"enabled", "severity"};
    const ThresholdKey* match = nullptr;
    for (const ThresholdKey& t : kThresholdKeys) {
      if (t.rule != rule) continue;
      known.push_back(t.key);
      if (t.key == key) match = &t;
    }
    if (!match)
      return Problem{at, unknown_name(fmt::format("setting of {}", to_string(rule)), key, known)};
    if (auto p = read_threshold(value, at, set.thresholds.*(match->field))) return p;
  }
  return std::nullopt;
}

std::optional<Problem> read_rules(const Json& rules, RuleSet& set) {
  if (!rules.is_object())
    return Problem{"/rules", "expected an object of rules, found " + value_text(rules)};
  for (const auto& [name, body] : rules.items()) {
    const std::string pointer = "/rules/" + name;
    const std::optional<Code> code = parse_code(name);
    if (!code || !rule_index(*code))
      return Problem{pointer, unknown_name("rule", name, rule_names())};
    if (body.is_boolean()) {
      set.enabled[*rule_index(*code)] = body.get<bool>();
    } else if (body.is_object()) {
      if (auto p = read_rule_object(body, *code, pointer, set)) return p;
    } else {
      return Problem{pointer,
                     "expected true, false or an object of settings, found " + value_text(body)};
    }
  }
  return std::nullopt;
}

std::optional<Problem> read_accessible_rooms(const Json& rooms, RuleSet& set) {
  if (!rooms.is_array())
    return Problem{"/accessible_rooms",
                   "expected an array of points [x, y], found " + value_text(rooms)};
  std::vector<Point2> points;
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    const Json& p = rooms[i];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number() ||
        !std::isfinite(p[0].get<double>()) || !std::isfinite(p[1].get<double>()))
      return Problem{fmt::format("/accessible_rooms/{}", i),
                     "expected a point [x, y] in metres, found " + value_text(p)};
    points.push_back({p[0].get<double>(), p[1].get<double>()});
  }
  set.accessible_rooms = std::move(points);
  return std::nullopt;
}

/// `habitable_rooms`: {"min_area": m², "corridor_width": m, "not_habitable": ["word", ...]}.
std::optional<Problem> read_habitable_rooms(const Json& body, RuleSet& set) {
  if (!body.is_object())
    return Problem{"/habitable_rooms", "expected an object of settings, found " + value_text(body)};
  HabitableRooms& h = set.habitable_rooms;
  for (const auto& [key, value] : body.items()) {
    const std::string at = "/habitable_rooms/" + key;
    if (key == "min_area" || key == "corridor_width") {
      if (auto p = read_threshold(value, at, key == "min_area" ? h.min_area : h.corridor_width))
        return p;
    } else if (key == "not_habitable") {
      if (!value.is_array() || !std::all_of(value.begin(), value.end(), [](const Json& w) {
            return w.is_string() && !w.get<std::string>().empty();
          }))
        return Problem{at, "expected an array of words (strings), found " + value_text(value)};
      h.not_habitable.clear();
      for (const Json& word : value)
        h.not_habitable.push_back(detail::lower_case(word.get<std::string>()));
    } else {
      return Problem{at, unknown_name("setting of habitable_rooms", key,
                                      {"min_area", "corridor_width", "not_habitable"})};
    }
  }
  return std::nullopt;
}

std::optional<Problem> read_header(const Json& doc, RuleSet& set) {
  for (const auto& [key, value] : doc.items())
    if (std::find(std::begin(kTopLevelKeys), std::end(kTopLevelKeys), key) ==
        std::end(kTopLevelKeys))
      return Problem{'/' + key, unknown_name("field", key,
                                             {std::begin(kTopLevelKeys), std::end(kTopLevelKeys)})};
  if (doc.contains("format") && doc["format"] != "roomcad-rules")
    return Problem{"/format", "expected \"roomcad-rules\", found " + value_text(doc["format"])};
  if (doc.contains("version") && doc["version"] != 1)
    return Problem{"/version", "expected 1, found " + value_text(doc["version"])};
  if (!doc.contains("base")) return std::nullopt;
  const Json& base = doc["base"];
  const std::optional<RuleSet> builtin =
      base.is_string() ? builtin_rule_set(base.get<std::string>()) : std::nullopt;
  if (!builtin)
    return Problem{"/base",
                   base.is_string()
                       ? unknown_name("rule set", base.get<std::string>(), builtin_rule_set_names())
                       : "expected a rule set name, found " + value_text(base)};
  set.enabled = builtin->enabled;
  return std::nullopt;
}

/// @return "line L, column C" of a byte offset in text.
std::string line_and_column(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
  const std::size_t start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  const std::size_t column = offset - (start == std::string_view::npos ? 0 : start + 1) + 1;
  return fmt::format("{}:{}", line, column);
}

}  // namespace

std::optional<std::size_t> rule_index(Code code) {
  const auto it = std::find(kRuleCodes.begin(), kRuleCodes.end(), code);
  if (it == kRuleCodes.end()) return std::nullopt;
  return static_cast<std::size_t>(it - kRuleCodes.begin());
}

bool RuleSet::is_enabled(Code code) const {
  const auto index = rule_index(code);
  return index && enabled[*index];
}

bool RuleSet::any_enabled() const {
  return std::any_of(enabled.begin(), enabled.end(), [](bool on) { return on; });
}

std::vector<std::string_view> builtin_rule_set_names() {
  return {"default", "accessibility", "insolation", "all"};
}

std::optional<RuleSet> builtin_rule_set(std::string_view name) {
  RuleSet set;
  set.name = std::string(name);
  if (name == "default") return set;
  if (name == "all") {
    set.enabled.fill(true);
    return set;
  }
  if (name == "insolation") {
    set.enabled[*rule_index(Code::insolation_short)] = true;
    return set;
  }
  if (name != "accessibility") return std::nullopt;
  for (const Code c : {Code::door_too_narrow, Code::door_clearance, Code::passage_too_narrow,
                       Code::no_turning_circle, Code::room_unreachable})
    set.enabled[*rule_index(c)] = true;
  return set;
}

Result<RuleSet> parse_rule_set(std::string_view text, const std::string& file) {
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    return Error{Code::usage_error,
                 fmt::format("{}:{}: not a rules file: invalid JSON", file,
                             line_and_column(text, e.byte == 0 ? 0 : e.byte - 1)),
                 Location{file, "", 0, 0}};
  }
  if (!doc.is_object())
    return usage_error(file,
                       {"", "expected a JSON object with \"rules\", found " + value_text(doc)});
  RuleSet set;
  set.name = file;
  std::optional<Problem> problem = read_header(doc, set);
  if (!problem && doc.contains("rules")) problem = read_rules(doc["rules"], set);
  if (!problem && doc.contains("accessible_rooms"))
    problem = read_accessible_rooms(doc["accessible_rooms"], set);
  if (!problem && doc.contains("habitable_rooms"))
    problem = read_habitable_rooms(doc["habitable_rooms"], set);
  if (problem) return usage_error(file, *problem);
  return set;
}

}  // namespace roomcad
