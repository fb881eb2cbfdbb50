// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/ifc_import.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "import/detail/ifc_elements.h"
#include "io/text_file.h"
#include "plan/arc_chords.h"

namespace roomcad {
namespace {

using ifc::Geometry;
using ifc::ImportState;
using step::Value;

constexpr double kDefaultLevelHeight = 2.8;

/// Levels from the storeys, in order of elevation; each storey's elements on its level.
void import_storeys(ImportState& s) {
  std::vector<std::pair<double, const step::Instance*>> storeys;
  for (const step::Instance& e : s.file.instances) {
    if (e.type != "IFCBUILDINGSTOREY") continue;
    s.handled.insert(e.id);
    double z = s.geometry.placement(Geometry::param(e, 5)).origin.z;
    if (Geometry::param(e, 5).kind != Value::Kind::ref && Geometry::param(e, 9).is_number())
      z = Geometry::param(e, 9).number;
    storeys.emplace_back(s.metres(s.metres_per_unit * z), &e);
  }
  std::stable_sort(storeys.begin(), storeys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::map<std::uint32_t, std::string> level_of_storey;
  for (std::size_t i = 0; i < storeys.size(); ++i) {
    const auto& [elevation, e] = storeys[i];
    Level level;
    level.id = s.unique_id(Geometry::param(*e, 2).text, "storey", e->id);
    level.elevation = elevation;
    level.height = i + 1 < storeys.size() && storeys[i + 1].first > elevation
                       ? s.metres(storeys[i + 1].first - elevation)
                       : kDefaultLevelHeight;
    s.elevation_of_level.emplace(level.id, level.elevation);
    level_of_storey.emplace(e->id, level.id);
    s.plan.levels.push_back(std::move(level));
  }
  for (const step::Instance& rel : s.file.instances) {
    if (rel.type != "IFCRELCONTAINEDINSPATIALSTRUCTURE") continue;
    const auto level = level_of_storey.find(Geometry::param(rel, 5).id);
    if (level == level_of_storey.end()) continue;
    for (const Value& element : Geometry::param(rel, 4).items)
      s.level_of_element.emplace(element.id, level->second);
  }
  // Doors and windows sit in their wall's storey, and openings in their wall.
}

/// The last level's height: up to its highest wall, if it has walls.
void fit_last_level(Plan& plan) {
  if (plan.levels.empty()) return;
  Level& last = plan.levels.back();
  double top = 0.0;
  for (const Wall& w : plan.walls)
    if (w.level == last.id) top = std::max(top, w.base + highest_height(w));
  if (top > 0.0) last.height = top;
}

/// Raises a model reaching below z = 0 so that its lowest point is at 0. @return the shift.
double raise_to_floor(Plan& plan, const std::unordered_map<std::string, double>& elevation) {
  double lowest = 0.0;
  auto at = [&elevation](const std::string& level) {
    return level.empty() ? 0.0 : elevation.at(level);
  };
  for (const Wall& w : plan.walls) lowest = std::min(lowest, at(w.level) + w.base);
  for (const Slab& s : plan.slabs) lowest = std::min(lowest, at(s.level) + s.top - s.thickness);
  if (lowest >= 0.0) return 0.0;
  const double shift = -lowest;
  for (Level& l : plan.levels) l.elevation = std::round((l.elevation + shift) * 1e6) / 1e6;
  for (Wall& w : plan.walls)
    if (w.level.empty()) w.base = std::round((w.base + shift) * 1e6) / 1e6;
  for (Slab& s : plan.slabs)
    if (s.level.empty()) s.top = std::round((s.top + shift) * 1e6) / 1e6;
  return shift;
}

/// The site: a grid of tiles covering every wall and slab with a margin, high enough for all.
void fit_site(Plan& plan, const IfcImportOptions& options) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY, top = 0.0;
  auto add = [&](Point2 p, double pad) {
    x0 = std::min(x0, p.x - pad), y0 = std::min(y0, p.y - pad), x1 = std::max(x1, p.x + pad),
    y1 = std::max(y1, p.y + pad);
  };
  auto elevation = [&plan](const std::string& id) {
    for (const Level& l : plan.levels)
      if (l.id == id) return l.elevation;
    return 0.0;
  };
  for (const Wall& w : plan.walls) {
    for (const Point2& p : chord_polyline(w, kDefaultChordTolerance)) add(p, w.thickness);
    top = std::max(top, elevation(w.level) + w.base + highest_height(w));
  }
  for (const Slab& s : plan.slabs) {
    for (const Point2& p : s.outline) add(p, 0.0);
    top = std::max(top, elevation(s.level) + s.top);
  }
  const double cell = options.cell_size;
  plan.site.cell_size = cell;
  plan.site.origin = {std::floor((x0 - options.site_margin) / cell) * cell,
                      std::floor((y0 - options.site_margin) / cell) * cell};
  plan.site.cells = {
      static_cast<std::int64_t>(std::ceil((x1 + options.site_margin - plan.site.origin.x) / cell)),
      static_cast<std::int64_t>(std::ceil((y1 + options.site_margin - plan.site.origin.y) / cell))};
  plan.site.max_height = std::ceil(top + options.site_margin);
  plan.site.tolerance = options.join_tolerance;
}

/// True for an instance that looks like a placed product: a GlobalId and an ObjectPlacement.
bool is_product(const ImportState& s, const step::Instance& e) {
  const Value& id = Geometry::param(e, 0);
  if (id.kind != Value::Kind::string || id.text.size() != 22) return false;
  const step::Instance* placement = s.geometry.get(Geometry::param(e, 5));
  return placement &&
         (placement->type == "IFCLOCALPLACEMENT" || placement->type == "IFCGRIDPLACEMENT");
}

std::size_t warn_skipped(ImportState& s) {
  std::size_t skipped = 0;
  for (const step::Instance& e : s.file.instances) {
    if (s.handled.contains(e.id) || e.type == "IFCSITE" || e.type == "IFCBUILDING" ||
        !is_product(s, e))
      continue;
    ++skipped;
    s.warn(Code::import_skipped_element, e,
           e.type == "IFCSPACE"
               ? "not imported: roomcad finds rooms from the walls"
               : "not imported: the importer reads walls, openings with their doors and "
                 "windows, slabs and storeys");
  }
  return skipped;
}

std::map<std::string, IfcEntityTally> tally_of(const ImportState& s) {
  std::map<std::string, IfcEntityTally> out;
  for (const step::Instance& e : s.file.instances) {
    const bool skipped = s.skipped.contains(e.id);
    if (!skipped && !s.read.contains(e.id)) continue;
    IfcEntityTally& t = out[e.type];
    if (skipped) {
      ++t.skipped;
      continue;
    }
    ++t.read;
    const auto approximated = s.approximated.find(e.id);
    if (approximated == s.approximated.end()) continue;
    ++t.approximated;
    t.distance = std::max(t.distance, approximated->second);
    t.unmeasured += s.unmeasured.contains(e.id);
  }
  return out;
}

}  // namespace

std::vector<std::string> format_tally(const IfcImport& import) {
  std::vector<std::string> out;
  for (const auto& [type, t] : import.tally) {
    std::string line = fmt::format("{}: {} read", type, t.read);
    if (t.approximated > 0) {
      line += fmt::format(" ({} approximated", t.approximated);
      if (t.approximated > t.unmeasured)
        line += fmt::format(", {:.3g} m at most from the file's geometry", t.distance);
      if (t.unmeasured > 0) line += fmt::format(", {} by a distance not measured", t.unmeasured);
      line += ")";
    }
    if (t.skipped > 0) line += fmt::format(", {} skipped", t.skipped);
    out.push_back(std::move(line));
  }
  return out;
}

bool is_step_text(std::string_view head) {
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  return start != std::string_view::npos && head.substr(start).starts_with("ISO-10303-21");
}

Result<IfcImport> import_ifc_text(std::string_view text, std::string_view file,
                                  const IfcImportOptions& options) {
  Result<step::File> parsed = step::parse(text, file);
  if (!parsed) return parsed.error();
  const step::File& f = parsed.value();
  if (!f.schema.starts_with("IFC2X3") && !f.schema.starts_with("IFC4"))
    return Result<IfcImport>::failure(
        Code::unsupported, fmt::format("{}: schema \"{}\" is not IFC2X3 or IFC4", file, f.schema));
  ImportState s(f);
  import_storeys(s);
  ifc::import_walls(s);
  ifc::import_curtain_walls(s);
  ifc::import_slabs(s);
  ifc::import_openings(s);
  ifc::import_site(s);
  if (s.plan.walls.empty() && s.plan.slabs.empty())
    return Result<IfcImport>::failure(
        Code::parse_error, fmt::format("{}: no wall or slab to import ({} walls and {} slabs "
                                       "in the file, none an extrusion the importer reads)",
                                       file, s.walls, s.slabs));
  IfcImport out;
  out.skipped = warn_skipped(s);
  out.tally = tally_of(s);
  for (const auto& [entity, walls] : s.walls_of)
    for (const std::size_t i : walls) out.wall_sources.emplace(s.plan.walls[i].id, entity);
  for (const auto& [type, t] : out.tally) {
    if (type.starts_with("IFCWALL") || type == "IFCCURTAINWALL") out.walls_read += t.read;
    if (type == "IFCOPENINGELEMENT") out.openings_read += t.read;
    if (type.starts_with("IFCSLAB")) out.slabs_read += t.read;
  }
  fit_last_level(s.plan);
  out.z_shift = raise_to_floor(s.plan, s.elevation_of_level);
  fit_site(s.plan, options);
  out.plan = std::move(s.plan);
  out.warnings = std::move(s.warnings);
  out.schema = f.schema;
  out.source_walls = s.walls;
  out.source_openings = s.openings;
  out.source_slabs = s.slabs;
  out.storeys = out.plan.levels.size();
  return out;
}

Result<IfcImport> import_ifc_file(const std::filesystem::path& path,
                                  const IfcImportOptions& options) {
  const Result<std::string> text = read_text_file(path);
  if (!text) return text.error();
  return import_ifc_text(text.value(), path.string(), options);
}

}  // namespace roomcad
