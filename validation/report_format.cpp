// SPDX-License-Identifier: GPL-3.0-or-later
#include "validation/report_format.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "validation/fix_edits.h"
#include "validation/report_tally.h"

namespace roomcad {
namespace {

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_number(double x) { return nlohmann::json(x).dump(); }

std::string json_point(const Point2& p) {
  return '[' + json_number(p.x) + ", " + json_number(p.y) + ']';
}

std::string_view op_name(FixEdit::Op op) {
  switch (op) {
    case FixEdit::Op::add: return "add";
    case FixEdit::Op::remove: return "rm";
    default: return "set";
  }
}

std::string json_edits(const std::vector<FixEdit>& edits, const std::string& plan_file) {
  std::string out = "[";
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const FixEdit& e = edits[i];
    out += (i ? ", " : "") + std::string("{\"op\": ") + json_string(std::string(op_name(e.op))) +
           ", \"id\": " + json_string(e.id);
    if (e.op == FixEdit::Op::remove) {
      out += std::string(", \"cascade\": ") + (e.cascade ? "true" : "false");
    } else {
      out += ", \"fields\": {";
      for (std::size_t k = 0; k < e.fields.size(); ++k)
        out += (k ? ", " : "") + json_string(e.fields[k].first) + ": " +
               json_string(e.fields[k].second);
      out += '}';
    }
    out += ", \"command\": " + json_string(edit_command(e, plan_file)) + '}';
  }
  return out + ']';
}

/// An item's extra fields beyond the spec's (id, status), as ", key: value..." text.
struct ItemExtras {
  const std::string* id = nullptr;
  std::optional<ItemStatus> status;
};

std::string json_item(const Diagnostic& d, const ItemExtras& extras, const std::string& plan_file) {
  std::string out = "{";
  if (extras.id) out += "\"id\": " + json_string(*extras.id) + ", ";
  if (extras.status)
    out += "\"status\": " + json_string(std::string(to_string(*extras.status))) + ", ";
  out += "\"code\": " + json_string(std::string(to_string(d.code))) + ", \"objects\": [";
  for (std::size_t i = 0; i < d.objects.size(); ++i)
    out += (i ? ", " : "") + json_string(d.objects[i]);
  out += "], \"message\": " + json_string(d.message);
  if (d.where) {
    out += ", \"where\": ";
    out += d.where->max ? '[' + json_point(d.where->min) + ", " + json_point(*d.where->max) + ']'
                        : json_point(d.where->min);
  }
  if (!d.fix.empty()) out += ", \"fix\": " + json_string(d.fix);
  if (!d.edits.empty()) out += ", \"edits\": " + json_edits(d.edits, plan_file);
  if (d.location) {
    out += ", \"file\": " + json_string(d.location->file);
    out += ", \"line\": " + std::to_string(d.location->line);
    out += ", \"column\": " + std::to_string(d.location->column);
    out += ", \"pointer\": " + json_string(d.location->pointer);
  }
  return out + '}';
}

/// The items of one severity (or all, for the fixed list), one per line.
std::string json_items(const Report& report, std::optional<Severity> severity,
                       const ReportFormatOptions& o, const std::vector<std::string>* ids,
                       const std::vector<ItemStatus>* status, const char* indent = "\n    ",
                       const char* close = "\n  ]") {
  std::string out;
  for (std::size_t i = 0; i < report.items.size(); ++i) {
    const Diagnostic& d = report.items[i];
    if (severity && d.severity != *severity) continue;
    out += out.empty() ? indent : std::string(",") + indent;
    ItemExtras extras;
    if (ids) extras.id = &(*ids)[i];
    if (status) extras.status = (*status)[i];
    out += json_item(d, extras, o.plan_file);
  }
  return out.empty() ? "[]" : '[' + out + close;
}

/// Ten significant digits: enough to place any problem on a site (a 1e-7 m gap still shows), while
/// a coordinate computed as 7.859999999999999 reads 7.86. JSON keeps the exact doubles.
/// Cost: O(1).
std::string text_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x == 0 ? 0.0 : x);  // no "-0"
  return buffer;
}

std::string text_point(const Point2& p) {
  return '(' + text_number(p.x) + ", " + text_number(p.y) + ')';
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + ' ' + word + (n == 1 ? "" : "s");
}

}  // namespace

std::string format_report_json(const Report& report, const ReportFormatOptions& o) {
  const ReportComparison* c = o.comparison;
  const std::vector<std::string> own_ids =
      o.ids && !c ? item_ids(report) : std::vector<std::string>{};
  const std::vector<std::string>* ids = c ? &c->ids : o.ids ? &own_ids : nullptr;
  const std::vector<ItemStatus>* status = c ? &c->status : nullptr;
  std::string out = std::string("{\n  \"ok\": ") + (report.ok() ? "true" : "false") +
                    ",\n  \"errors\": " + json_items(report, Severity::error, o, ids, status) +
                    ",\n  \"warnings\": " + json_items(report, Severity::warning, o, ids, status);
  if (c) {
    const auto added = std::count(c->status.begin(), c->status.end(), ItemStatus::added);
    out += ",\n  \"baseline\": {\"file\": " + json_string(o.baseline_file) +
           ", \"new\": " + std::to_string(added) + ", \"unchanged\": " +
           std::to_string(c->status.size() - static_cast<std::size_t>(added)) + ", \"fixed\": " +
           json_items(c->fixed, std::nullopt, o, &c->fixed_ids, nullptr, "\n      ", "\n    ]") +
           '}';
  }
  return out + "\n}\n";
}

std::string format_item_json(const Diagnostic& item, const std::string& plan_file) {
  return json_item(item, {}, plan_file);
}

std::string format_report_text(const Report& report, bool colour, const ReportFormatOptions& o) {
  const char* bold = colour ? "\033[1m" : "";
  const char* reset = colour ? "\033[0m" : "";
  std::string out;
  const auto block = [&](const Diagnostic& d, std::string_view status) {
    const bool error = d.severity == Severity::error;
    if (!status.empty()) out += std::string(status) + ' ';
    if (colour) out += error ? "\033[1;31m" : "\033[1;33m";
    out += error ? "error" : "warning";
    out += reset;
    out += std::string(bold) + '[' + std::string(to_string(d.code)) + ']' + reset;
    for (std::size_t i = 0; i < d.objects.size(); ++i) out += (i ? ", " : " ") + d.objects[i];
    out += ": " + d.message + '\n';
    if (d.where) {
      out += "  at: " +
             (d.where->max ? text_point(d.where->min) + " .. " + text_point(*d.where->max)
                           : text_point(d.where->min)) +
             " m\n";
    }
    if (!d.fix.empty()) out += "  fix: " + d.fix + '\n';
    for (const FixEdit& e : d.edits) out += "  edit: " + edit_command(e, o.plan_file) + '\n';
  };
  const std::size_t shown = std::min(report.items.size(), o.max_items);
  for (std::size_t i = 0; i < shown; ++i)
    block(report.items[i], o.comparison ? to_string(o.comparison->status[i]) : "");
  if (shown < report.items.size())
    out += fmt::format(
        "... and {} more (--max-findings N prints N in full; --format json lists "
        "them all)\n",
        report.items.size() - shown);
  if (o.comparison && !o.comparison->fixed.items.empty()) {
    out += "fixed since " + o.baseline_file + ":\n";
    for (const Diagnostic& d : o.comparison->fixed.items) block(d, "fixed");
  }
  if (report.items.size() >= kTallyFrom || shown < report.items.size())
    out += format_report_tally(report, o.item_levels ? *o.item_levels : std::vector<std::string>{});
  return out;
}

std::string format_report_summary(const Report& report, const ReportFormatOptions& o) {
  std::string out = report.items.empty() ? "no problems"
                                         : plural(report.error_count(), "error") + ", " +
                                               plural(report.warning_count(), "warning");
  if (const ReportComparison* c = o.comparison) {
    const auto added =
        static_cast<std::size_t>(std::count(c->status.begin(), c->status.end(), ItemStatus::added));
    out += "; against " + o.baseline_file + ": " + std::to_string(added) + " new, " +
           std::to_string(c->status.size() - added) + " unchanged, " +
           std::to_string(c->fixed.items.size()) + " fixed";
  }
  return out;
}

}  // namespace roomcad
