#include "validation/report_format.h"

#include <cstdio>

#include <nlohmann/json.hpp>

namespace roomcad {
namespace {

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_number(double x) { return nlohmann::json(x).dump(); }

std::string json_point(const Point2& p) {
  return '[' + json_number(p.x) + ", " + json_number(p.y) + ']';
}

std::string json_item(const Diagnostic& d) {
  std::string out = "{\"code\": " + json_string(std::string(to_string(d.code))) + ", \"objects\": [";
  for (std::size_t i = 0; i < d.objects.size(); ++i)
    out += (i ? ", " : "") + json_string(d.objects[i]);
  out += "], \"message\": " + json_string(d.message);
  if (d.where) {
    out += ", \"where\": ";
    out += d.where->max ? '[' + json_point(d.where->min) + ", " + json_point(*d.where->max) + ']'
                        : json_point(d.where->min);
  }
  if (!d.fix.empty()) out += ", \"fix\": " + json_string(d.fix);
  if (d.location) {
    out += ", \"file\": " + json_string(d.location->file);
    out += ", \"line\": " + std::to_string(d.location->line);
    out += ", \"column\": " + std::to_string(d.location->column);
    out += ", \"pointer\": " + json_string(d.location->pointer);
  }
  return out + '}';
}

std::string json_items(const Report& report, Severity severity) {
  std::string out;
  for (const Diagnostic& d : report.items) {
    if (d.severity != severity) continue;
    out += out.empty() ? "\n    " : ",\n    ";
    out += json_item(d);
  }
  return out.empty() ? "[]" : '[' + out + "\n  ]";
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

std::string format_report_json(const Report& report) {
  return std::string("{\n  \"ok\": ") + (report.ok() ? "true" : "false") +
         ",\n  \"errors\": " + json_items(report, Severity::error) +
         ",\n  \"warnings\": " + json_items(report, Severity::warning) + "\n}\n";
}

std::string format_report_text(const Report& report, bool colour) {
  const char* bold = colour ? "\033[1m" : "";
  const char* reset = colour ? "\033[0m" : "";
  std::string out;
  for (const Diagnostic& d : report.items) {
    const bool error = d.severity == Severity::error;
    if (colour) out += error ? "\033[1;31m" : "\033[1;33m";
    out += error ? "error" : "warning";
    out += reset;
    out += std::string(bold) + '[' + std::string(to_string(d.code)) + ']' + reset;
    for (std::size_t i = 0; i < d.objects.size(); ++i) out += (i ? ", " : " ") + d.objects[i];
    out += ": " + d.message + '\n';
    if (d.where) {
      out += "  at: " + (d.where->max ? text_point(d.where->min) + " .. " + text_point(*d.where->max)
                                      : text_point(d.where->min)) + " m\n";
    }
    if (!d.fix.empty()) out += "  fix: " + d.fix + '\n';
  }
  return out;
}

std::string format_report_summary(const Report& report) {
  if (report.items.empty()) return "no problems";
  return plural(report.error_count(), "error") + ", " + plural(report.warning_count(), "warning");
}

}  // namespace roomcad
