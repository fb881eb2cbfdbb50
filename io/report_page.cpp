// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/report_page.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

#include "geometry/rooms.h"
#include "io/image_io.h"
#include "io/svg_writer.h"
#include "render/render_request.h"
#include "render/renderer.h"
#include "solid/build_model.h"
#include "validation/report_tally.h"
#include "validation/room_labels.h"

namespace roomcad {
namespace {

// The page's style and script, written for it: no framework, nothing fetched.
constexpr std::string_view kStyle = R"(
body { font: 14px/1.4 sans-serif; margin: 0; color: #222; }
header, section { padding: 8px 16px; }
h1 { font-size: 20px; margin: 4px 0; }
h2 { font-size: 16px; margin: 12px 0 4px; }
.pass { color: #080; } .fail { color: #c00; }
table.counts { border-collapse: collapse; } .counts td, .counts th { padding: 2px 10px; text-align: left; }
#main { display: flex; gap: 16px; align-items: flex-start; }
#plans { flex: 3; min-width: 0; position: sticky; top: 0; max-height: 100vh; overflow: auto; }
#list { flex: 2; min-width: 280px; }
figure.plan { margin: 0 0 12px; border: 1px solid #ccc; }
figure.plan figcaption { padding: 2px 6px; background: #f4f4f4; }
svg.plan { width: 100%; height: 60vh; display: block; background: #fff; }
.room { fill: #f3efe6; } .slab { fill: #e2ddd0; fill-rule: evenodd; }
.wall { fill: #444; } .opening { fill: #fff; stroke: #444; stroke-width: 0.02; }
.selected { fill: #d00000 !important; stroke: #d00000 !important; }
.opening.selected { fill: #ffb0b0 !important; }
#filters select { margin-right: 8px; }
ol.findings { padding-left: 0; list-style: none; max-height: 70vh; overflow: auto; }
li.finding, li.fixed, li.edit { border-left: 4px solid #c00; margin: 4px 0; padding: 4px 8px; cursor: pointer; }
li.warning { border-left-color: #d90; } li.fixed { border-left-color: #080; cursor: default; }
li.edit { border-left-color: #06c; }
li.current { background: #fde8e8; outline: 1px solid #c00; }
li.hidden { display: none; }
.code { font-weight: bold; } .fix { color: #555; } .status { font-size: 12px; color: #555; }
img.picture { max-width: 100%; border: 1px solid #ccc; }
)";

constexpr std::string_view kScript = R"(
(function () {
  const items = Array.from(document.querySelectorAll('li.finding, li.edit'));
  const byId = new Map();
  document.querySelectorAll('[data-id]').forEach(function (e) {
    const id = e.getAttribute('data-id');
    if (!byId.has(id)) byId.set(id, []);
    byId.get(id).push(e);
  });
  const plans = Array.from(document.querySelectorAll('svg.plan'));
  plans.forEach(function (s) { s.dataset.home = s.getAttribute('viewBox'); });
  let current = -1;
  const panel = document.getElementById('plans');
  function zoom(li) {
    const where = li.dataset.where;
    let shown = null;
    plans.forEach(function (s) {
      const level = s.dataset.level;
      if (!where || (li.dataset.level && level !== li.dataset.level)) {
        s.setAttribute('viewBox', s.dataset.home);
        return;
      }
      if (!shown) shown = s.parentNode;
      const w = where.split(' ').map(Number);
      const m = Math.max(2.5, Math.max(w[2] - w[0], w[3] - w[1]));
      s.setAttribute('viewBox', [w[0] - m, -w[3] - m, w[2] - w[0] + 2 * m, w[3] - w[1] + 2 * m].join(' '));
    });
    if (shown) panel.scrollTop = shown.offsetTop - panel.offsetTop;
  }
  function select(i) {
    document.querySelectorAll('.selected').forEach(function (e) { e.classList.remove('selected'); });
    if (current >= 0) items[current].classList.remove('current');
    current = i;
    const li = items[i];
    li.classList.add('current');
    li.dataset.objects.split(' ').forEach(function (id) {
      (byId.get(id) || []).forEach(function (e) { e.classList.add('selected'); });
    });
    zoom(li);
    li.scrollIntoView({block: 'nearest'});
    if (location.hash !== '#' + li.id) history.replaceState(null, '', '#' + li.id);
  }
  function visible(i) { return !items[i].classList.contains('hidden'); }
  function step(by) {
    for (let i = current + by; i >= 0 && i < items.length; i += by)
      if (visible(i)) { select(i); return; }
  }
  items.forEach(function (li, i) { li.addEventListener('click', function () { select(i); }); });
  document.addEventListener('keydown', function (e) {
    if (e.target.tagName === 'SELECT') return;
    if (e.key === 'ArrowDown' || e.key === 'j') { step(1); e.preventDefault(); }
    if (e.key === 'ArrowUp' || e.key === 'k') { step(-1); e.preventDefault(); }
  });
  const filters = Array.from(document.querySelectorAll('#filters select'));
  function filter() {
    items.forEach(function (li) {
      const shown = filters.every(function (f) {
        return f.value === '' || li.dataset[f.dataset.key] === f.value;
      });
      li.classList.toggle('hidden', !shown);
    });
  }
  filters.forEach(function (f) { f.addEventListener('change', filter); });
  function fromHash() {
    const li = location.hash ? document.getElementById(location.hash.slice(1)) : null;
    const i = items.indexOf(li);
    if (i >= 0 && i !== current) select(i);
  }
  window.addEventListener('hashchange', fromHash);
  fromHash();
})();
)";

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t k) {
      return k < bytes.size() ? std::uint32_t(static_cast<unsigned char>(bytes[k])) : 0u;
    };
    const std::uint32_t v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += kDigits[v >> 18 & 63];
    out += kDigits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? kDigits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

std::string num(double x) { return format_svg_number(x); }

/// Plan points as SVG points: y up in the plan is y down on screen.
std::string points_text(std::span<const Point2> points) {
  std::string out;
  for (const Point2& p : points)
    out += fmt::format("{}{},{}", out.empty() ? "" : " ", num(p.x), num(-p.y));
  return out;
}

bool finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

/// The box of everything drawn on one level, in plan coordinates.
struct Box {
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  void add(Point2 p) {
    lo_x = std::min(lo_x, p.x), lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
  }
  [[nodiscard]] bool empty() const { return !(lo_x <= hi_x); }
};

/// The rectangle from `a` to `b` (along a wall's centre line), `half` to either side; nothing
/// for a line of no length or coordinates that are not finite.
std::optional<std::array<Point2, 4>> band(Point2 a, Point2 b, double half) {
  const double dx = b.x - a.x, dy = b.y - a.y, length = std::hypot(dx, dy);
  if (!finite(a) || !finite(b) || !(length > 0) || !std::isfinite(half)) return std::nullopt;
  const double nx = -dy / length * half, ny = dx / length * half;
  return std::array<Point2, 4>{Point2{a.x + nx, a.y + ny}, Point2{b.x + nx, b.y + ny},
                               Point2{b.x - nx, b.y - ny}, Point2{a.x - nx, a.y - ny}};
}

void add_polygon(std::string& svg, Box& box, std::string_view css, std::string_view id,
                 std::span<const Point2> points) {
  for (const Point2& p : points) box.add(p);
  svg += fmt::format("<polygon class=\"{}\" data-id=\"{}\" points=\"{}\"/>\n", css, escape_xml(id),
                     points_text(points));
}

/// The floor plan of one level: rooms, slabs, walls (their centre-line rectangles, arcs as
/// their chord) and openings (their rectangles in their walls), each with its object's id.
std::string level_plan(const Plan& plan, const std::string& level) {
  std::string body;
  Box box;
  std::vector<Room> rooms = find_rooms_on_level(plan, level);
  const std::vector<const RoomLabel*> labels = room_labels(rooms, plan);
  for (std::size_t r = 0; r < rooms.size(); ++r) {
    const std::string id = labels[r] ? labels[r]->id : fmt::format("room-{}", r + 1);
    add_polygon(body, box, "room", id, rooms[r].outline);
  }
  for (const Slab& s : plan.slabs) {
    if (s.level != level || s.outline.size() < 3) continue;
    std::string d;  // appended piece by piece: GCC 12 warns (-Wrestrict) on `"M" + ...`
    for (const Polygon* ring : {&s.outline}) d.append("M").append(points_text(*ring)).append("Z");
    for (const Polygon& hole : s.holes) d.append("M").append(points_text(hole)).append("Z");
    for (const Point2& p : s.outline) box.add(p);
    body += fmt::format("<path class=\"slab\" data-id=\"{}\" d=\"{}\"/>\n", escape_xml(s.id), d);
  }
  std::unordered_map<std::string_view, const Wall*> walls;
  for (const Wall& w : plan.walls) {
    if (w.level != level) continue;
    walls.emplace(w.id, &w);
    if (const auto r = band(w.from, w.to, w.thickness / 2))
      add_polygon(body, box, "wall", w.id, *r);
  }
  for (const Opening& o : plan.openings) {
    const auto host = walls.find(o.wall);
    if (host == walls.end()) continue;
    const Wall& w = *host->second;
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    if (!(length > 0)) continue;
    const auto at = [&](double u) {
      return Point2{w.from.x + (w.to.x - w.from.x) * u / length,
                    w.from.y + (w.to.y - w.from.y) * u / length};
    };
    if (const auto r = band(at(o.offset), at(o.offset + o.width), w.thickness * 0.6))
      add_polygon(body, box, "opening", o.id, *r);
  }
  if (box.empty()) box = {0, 0, 1, 1};
  const double margin = 0.05 * std::max(box.hi_x - box.lo_x, box.hi_y - box.lo_y) + 0.5;
  const std::string view =
      fmt::format("{} {} {} {}", num(box.lo_x - margin), num(-box.hi_y - margin),
                  num(box.hi_x - box.lo_x + 2 * margin), num(box.hi_y - box.lo_y + 2 * margin));
  return fmt::format(
      "<figure class=\"plan\"><figcaption>{}</figcaption>\n<svg class=\"plan\" "
      "xmlns=\"http://www.w3.org/2000/svg\" data-level=\"{}\" viewBox=\"{}\" "
      "preserveAspectRatio=\"xMidYMid meet\">\n{}</svg></figure>\n",
      level.empty() ? std::string("plan") : "level " + escape_xml(level), escape_xml(level), view,
      body);
}

/// The levels drawn: the plan's (or the one asked), then "" for objects on none.
std::vector<std::string> levels_drawn(const Plan& plan, const std::string& only) {
  if (!only.empty()) return {only};
  std::vector<std::string> levels;
  for (const Level& l : plan.levels) levels.push_back(l.id);
  const bool unlevelled =
      plan.levels.empty() || std::any_of(plan.walls.begin(), plan.walls.end(),
                                         [](const Wall& w) { return w.level.empty(); });
  if (unlevelled) levels.emplace_back();
  return levels;
}

std::string where_text(const Diagnostic& d) {
  if (!d.where) return "";
  const Point2 lo = d.where->min, hi = d.where->max.value_or(d.where->min);
  if (!finite(lo) || !finite(hi)) return "";
  return fmt::format("{} {} {} {}", num(lo.x), num(lo.y), num(hi.x), num(hi.y));
}

std::string severity_of(const Diagnostic& d) {
  return d.severity == Severity::error ? "error" : "warning";
}

std::string item_html(const Diagnostic& d, std::string_view css, std::string_view id,
                      std::string_view level, std::string_view status) {
  std::string objects;
  for (const std::string& o : d.objects) objects += (objects.empty() ? "" : " ") + o;
  std::string out = fmt::format(
      "<li class=\"{} {}\"{} data-code=\"{}\" data-objects=\"{}\" data-level=\"{}\" "
      "data-severity=\"{}\" data-where=\"{}\" tabindex=\"0\">",
      css, severity_of(d), id.empty() ? "" : fmt::format(" id=\"{}\"", id), to_string(d.code),
      escape_xml(objects), escape_xml(level), severity_of(d), where_text(d));
  if (!status.empty()) out += fmt::format("<span class=\"status\">{}</span> ", status);
  out += fmt::format("<span class=\"code\">{}</span> {}", to_string(d.code), escape_xml(d.message));
  if (!d.fix.empty()) out += fmt::format("<div class=\"fix\">fix: {}</div>", escape_xml(d.fix));
  return out + "</li>\n";
}

/// A table of counts: rows by name, columns errors and warnings.
std::string counts_table(std::string_view heading, const std::vector<FindingCount>& rows) {
  std::string out = fmt::format(
      "<table class=\"counts\"><tr><th>{}</th><th>errors</th><th>warnings</th></tr>\n", heading);
  for (const FindingCount& row : rows)
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", escape_xml(row.name),
                       row.errors, row.warnings);
  return out + "</table>\n";
}

std::string options_html(std::string_view key, std::string_view all,
                         const std::vector<std::string>& values) {
  std::string out = fmt::format("<select data-key=\"{}\"><option value=\"\">{}</option>", key, all);
  for (const std::string& v : values)
    out += fmt::format("<option value=\"{}\">{}</option>", escape_xml(v),
                       v.empty() ? std::string("(no level)") : escape_xml(v));
  return out + "</select>";
}

}  // namespace

std::string render_picture_png(const Plan& plan) {
  RenderRequest request;
  request.width = 960;
  request.height = 540;
  const Result<RenderOptions> options = make_render_options(request, plan);
  if (!options) return {};
  try {
    const Model model = build_model(plan, BuildOptions{.parts = options.value().parts});
    FrameBuffers frame;
    render_model(model, options.value(), frame);
    const Result<std::string> png = png_bytes(frame.color);
    return png ? png.value() : std::string();
  } catch (const PreconditionError& e) {
    std::fprintf(stderr, "roomcad report: no picture of the model: %s\n", e.what());
    return {};
  }
}

std::string make_report_page(const ReportPageInput& in) {
  const Plan& plan = *in.plan;
  const Report& report = *in.report;
  const auto level_of = [&](std::size_t i) -> std::string {
    return in.item_levels ? (*in.item_levels)[i] : std::string();
  };
  std::vector<std::size_t> shown;  // items on the level asked, or all
  for (std::size_t i = 0; i < report.items.size(); ++i)
    if (in.level.empty() || level_of(i) == in.level) shown.push_back(i);

  std::vector<FindingCount> by_code, by_level;
  std::vector<std::string> item_level_names;  // the filter's values: "" for no level
  for (const std::size_t i : shown) {
    const Diagnostic& d = report.items[i];
    count_finding(by_code, to_string(d.code), d);
    count_finding(by_level, level_of(i).empty() ? "(no level)" : level_of(i), d);
    if (std::find(item_level_names.begin(), item_level_names.end(), level_of(i)) ==
        item_level_names.end())
      item_level_names.push_back(level_of(i));
  }
  std::vector<std::string> codes;
  for (const FindingCount& c : by_code) codes.push_back(c.name);
  const bool passes = report.ok();
  std::string page = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>roomcad report: "
      "{}</title>\n<style>{}</style></head><body>\n<header><h1>{}</h1>\n",
      escape_xml(in.title), kStyle, escape_xml(in.title));
  std::string level_list;
  for (const Level& l : plan.levels) level_list += (level_list.empty() ? "" : ", ") + l.id;
  page += fmt::format(
      "<p id=\"verdict\" class=\"{}\">{}: {} errors, {} warnings{}</p>\n<p>{} walls, {} openings, "
      "{} slabs; levels: {}</p></header>\n",
      passes ? "pass" : "fail", passes ? "passes" : "fails", report.error_count(),
      report.warning_count(),
      in.comparison ? fmt::format(" (against {})", escape_xml(in.baseline_file)) : "",
      plan.walls.size(), plan.openings.size(), plan.slabs.size(),
      level_list.empty() ? std::string("none") : escape_xml(level_list));
  page += "<section id=\"summary\"><h2>Findings by code and level</h2>\n";
  page += counts_table("code", by_code);
  if (!plan.levels.empty()) page += counts_table("level", by_level);
  page += "</section>\n<div id=\"main\"><section id=\"plans\"><h2>Plans</h2>\n";
  for (const std::string& level : levels_drawn(plan, in.level)) page += level_plan(plan, level);
  page += "</section>\n<section id=\"list\"><h2>Findings</h2>\n<div id=\"filters\">";
  page += options_html("code", "every code", codes);
  page += options_html("level", "every level", item_level_names);
  page += options_html("severity", "errors and warnings", {"error", "warning"});
  page += "</div>\n<ol class=\"findings\">\n";
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const std::size_t i = shown[k];
    const std::string status =
        in.comparison ? std::string(to_string(in.comparison->status[i])) : std::string();
    page += item_html(report.items[i], "finding", fmt::format("finding-{}", k + 1), level_of(i),
                      status);
  }
  page += "</ol>\n";
  if (in.comparison) {
    page += fmt::format("<h2>Fixed since {}</h2>\n<ol class=\"fixed\">\n",
                        escape_xml(in.baseline_file));
    for (const Diagnostic& d : in.comparison->fixed.items)
      page += item_html(d, "fixed", "", "", "fixed");
    page += "</ol>\n";
  }
  if (in.repaired) {
    page += fmt::format("<h2>Repair: {} edits</h2>\n<ol class=\"edits\">\n", in.edits.size());
    for (std::size_t k = 0; k < in.edits.size(); ++k) {
      std::string objects;
      for (const std::string& o : in.edits[k].objects) objects += (objects.empty() ? "" : " ") + o;
      page += fmt::format(
          "<li class=\"edit\" id=\"edit-{}\" data-objects=\"{}\" tabindex=\"0\">{}</li>\n", k + 1,
          escape_xml(objects), escape_xml(in.edits[k].text));
    }
    page += "</ol>\n";
  }
  page += "</section></div>\n";
  if (!in.picture_png.empty())
    page += fmt::format(
        "<section id=\"picture\"><h2>The model</h2><img class=\"picture\" alt=\"the model, "
        "rendered\" src=\"data:image/png;base64,{}\"></section>\n",
        base64(in.picture_png));
  page += fmt::format("<script>{}</script>\n</body></html>\n", kScript);
  return page;
}

}  // namespace roomcad
