// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/sweethome3d_import.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "core/box.h"
#include "import/detail/sh3d_archive.h"
#include "import/detail/sh3d_compass.h"
#include "import/detail/sh3d_home.h"
#include "import/detail/sh3d_levels.h"
#include "import/detail/sh3d_openings.h"
#include "import/detail/sh3d_rooms.h"
#include "import/detail/sh3d_walls.h"
#include "io/plan_json.h"
#include "io/text_file.h"
#include "plan/plan_levels.h"

namespace roomcad {
namespace {

/// What a home covers: its box in plan and its highest top.
struct HomeExtent {
  Box2 plan = empty_box2();
  double top = 0.0;
};

/// Box around the walls' centre lines (an arc's chords) grown by half their thickness (the
/// margin covers mitres) and the slabs, up to the highest wall top, slab top or level top.
HomeExtent bounds_of(const Plan& plan, const std::vector<sh3d::PlacedWall>& walls) {
  HomeExtent box;
  const auto add = [&box](Point2 p, double r) {
    add_point(box.plan, p.x - r, p.y - r);
    add_point(box.plan, p.x + r, p.y + r);
  };
  for (const sh3d::PlacedWall& w : walls) {
    for (const Point2 p : w.polyline) add(p, w.wall.thickness / 2);
    const double height = std::max(w.wall.height, w.wall.height_at_end.value_or(0.0));
    box.top = std::max(box.top, w.base_z + height);
  }
  for (const Slab& s : plan.slabs) {
    for (const Point2 p : s.outline) add(p, 0.0);
    box.top = std::max(box.top, top_z(plan, s));
  }
  for (const Level& l : plan.levels) box.top = std::max(box.top, l.elevation + l.height);
  return box;
}

Site make_site(const HomeExtent& box, const Sh3dImportOptions& options) {
  const double cell = options.cell_size;
  const Point2 origin{std::floor((box.plan.min_x - options.site_margin) / cell) * cell,
                      std::floor((box.plan.min_y - options.site_margin) / cell) * cell};
  auto cells = [&](double from, double to) {
    return static_cast<std::int64_t>(std::ceil((to + options.site_margin - from) / cell));
  };
  Site site;
  site.origin = origin;
  site.cells = {cells(origin.x, box.plan.max_x), cells(origin.y, box.plan.max_y)};
  site.cell_size = cell;
  site.max_height = std::ceil(box.top) + 1.0;
  site.tolerance = options.join_tolerance;
  site.chord_tolerance = options.chord_tolerance;
  return site;
}

/// Sweet Home 3D's field of view is horizontal; the plan's is vertical (for a 4:3 picture).
Camera make_camera(const sh3d::CameraRecord& c, std::string id, Point2 centre, double z_shift) {
  const Vec3 eye{c.eye.x, c.eye.y, c.eye.z + z_shift};
  // Aim at the point of the view line nearest the home's centre (at least 1 m ahead).
  const double ahead =
      std::max(1.0, (centre.x - eye.x) * c.direction.x + (centre.y - eye.y) * c.direction.y);
  const double vertical = 2 * std::atan(std::tan(c.field_of_view / 2) * 0.75);
  Camera camera;
  camera.id = std::move(id);
  camera.eye = eye;
  camera.target = {eye.x + ahead * c.direction.x, eye.y + ahead * c.direction.y,
                   eye.z + ahead * c.direction.z};
  camera.fov_deg = vertical * 180 / std::numbers::pi;
  return camera;
}

std::vector<Camera> make_cameras(const sh3d::Home& home, const HomeExtent& box, double z_shift) {
  const Point2 centre{(box.plan.min_x + box.plan.max_x) / 2, (box.plan.min_y + box.plan.max_y) / 2};
  std::vector<Camera> cameras;
  for (const sh3d::CameraRecord& c : home.cameras) {
    if (c.kind == "observerCamera") cameras.push_back(make_camera(c, "observer", centre, z_shift));
    // The aerial view is kept unless it looks straight down (its `up` would be undefined).
    if (c.kind == "topCamera" && std::abs(c.direction.z) < 0.95)
      cameras.push_back(make_camera(c, "aerial", centre, z_shift));
  }
  const double span = std::max(box.plan.max_x - box.plan.min_x, box.plan.max_y - box.plan.min_y);
  Camera overview;  // from the south-west, above: the whole home in a 50 degree view
  overview.id = "overview";
  overview.target = {centre.x, centre.y, box.top / 3};
  overview.eye = {centre.x - 0.7 * span, centre.y - 1.1 * span, box.top / 3 + 1.0 * span};
  cameras.push_back(overview);
  Camera plan;  // straight down, north up, the whole home in view
  plan.id = "plan";
  plan.projection = Projection::orthographic;
  plan.eye = {centre.x, centre.y, box.top + 10.0};
  plan.target = {centre.x, centre.y, 0.0};
  plan.up = {0.0, 1.0, 0.0};
  plan.view_height = span + 1.0;
  cameras.push_back(plan);
  return cameras;
}

/// The error for a home that would make a plan of more objects than the plan reader reads back.
std::string too_many_objects(std::string_view file, std::size_t walls, std::size_t items,
                             std::string_view walls_are, std::string_view items_are) {
  return fmt::format("{}: {} {} {} {}; a plan may hold at most {} of each kind", file, walls,
                     walls_are, items, items_are, kMaxPlanObjects);
}

/// @return the centimetres that raise the home so that its lowest level's floor band (or its
/// walls without a level) starts at z = 0: the format has no negative z.
double z_shift_of(const sh3d::Home& home, const std::vector<sh3d::Level>& selected) {
  double lowest = std::numeric_limits<double>::max();
  for (const sh3d::Level& l : selected)
    lowest = std::min(lowest, sh3d::level_base(home, l.id).base_cm);
  for (const sh3d::WallRecord& w : home.walls)
    if (w.level.empty()) lowest = std::min(lowest, 0.0);
  return lowest == std::numeric_limits<double>::max() ? 0.0 : 0.0 - lowest;  // no -0
}

/// The ids of the home's walls, items and rooms: a level may not take one as its id.
std::set<std::string, std::less<>> ids_of(const sh3d::Home& home) {
  std::set<std::string, std::less<>> ids;
  for (const sh3d::WallRecord& w : home.walls) ids.insert(w.id);
  for (const sh3d::ItemRecord& i : home.items) ids.insert(i.id);
  for (const sh3d::RoomRecord& r : home.rooms) {
    ids.insert(r.id);
    ids.insert(r.id + "-ceiling");
  }
  return ids;
}

/// The level id selected by name, "" for all levels.
Result<std::string> select_level(const sh3d::Home& home, const Sh3dImportOptions& options,
                                 std::string_view file) {
  if (!options.level) return std::string();
  std::string names;
  for (const sh3d::Level& l : home.levels) {
    if (l.name == *options.level) return l.id;
    names += fmt::format("{}'{}'", names.empty() ? "" : ", ", l.name);
  }
  return Result<std::string>::failure(
      Code::usage_error,
      fmt::format("{}: --level '{}' names no level of the home (its levels: {})", file,
                  *options.level, names.empty() ? "none, it has a single unnamed level" : names));
}

}  // namespace

Result<Sh3dImport> import_sweethome3d_text(std::string_view xml, std::string_view file,
                                           const Sh3dImportOptions& options) {
  Result<sh3d::Home> parsed = sh3d::parse_home_xml(xml, file);
  if (!parsed) return parsed.error();
  sh3d::Home& home = parsed.value();
  const Result<std::string> level = select_level(home, options, file);
  if (!level) return level.error();
  auto on_level = [&](const std::string& id) { return !options.level || id == level.value(); };
  std::erase_if(home.walls, [&](const sh3d::WallRecord& w) { return !on_level(w.level); });
  std::erase_if(home.items, [&](const sh3d::ItemRecord& i) { return !on_level(i.level); });
  std::erase_if(home.rooms, [&](const sh3d::RoomRecord& r) { return !on_level(r.level); });
  // Which level is the lowest stays the home's: home.levels is kept whole.
  std::vector<sh3d::Level> selected = home.levels;
  std::erase_if(selected, [&](const sh3d::Level& l) { return !on_level(l.id); });
  if (home.walls.empty())
    return Result<Sh3dImport>::failure(Code::invalid_value,
                                       fmt::format("{}: no <wall> to import", file));
  if (home.walls.size() > kMaxPlanObjects || home.items.size() > kMaxPlanObjects)
    return Result<Sh3dImport>::failure(
        Code::too_large, too_many_objects(file, home.walls.size(), home.items.size(), "<wall> and",
                                          "<doorOrWindow> elements"));
  // Matching is O(walls x (items + levels)): bounded, so that no file can make it hang.
  const double pairs = static_cast<double>(home.walls.size()) *
                       static_cast<double>(home.items.size() + home.levels.size());
  if (pairs > kMaxImportPairs)
    return Result<Sh3dImport>::failure(
        Code::too_large,
        fmt::format("{}: {} <wall> and {} <doorOrWindow> and <level> elements; at most {:.0f} "
                    "pairs of them "
                    "are matched (a home of a thousand walls and a thousand items has a million)",
                    file, home.walls.size(), home.items.size() + home.levels.size(),
                    kMaxImportPairs));

  Sh3dImport out;
  out.source_walls = home.walls.size();
  out.source_items = home.items.size();
  const double z_shift_cm = z_shift_of(home, selected);
  out.z_shift = z_shift_cm / 100;
  const std::vector<sh3d::PlacedLevel> levels =
      sh3d::place_levels(home, selected, z_shift_cm, ids_of(home));
  for (const sh3d::PlacedLevel& l : levels) out.plan.levels.push_back(l.level);
  sh3d::WallOptions wall_options;
  wall_options.chord_tolerance = options.chord_tolerance.value_or(kDefaultChordTolerance);
  wall_options.z_shift_cm = z_shift_cm;
  const std::vector<sh3d::PlacedWall> walls =
      sh3d::convert_walls(home, home.walls, levels, wall_options, out.warnings);
  for (const sh3d::PlacedWall& w : walls) out.plan.walls.push_back(w.wall);
  // With every wall left out, the site's box would be empty.
  if (out.plan.walls.empty())
    return Result<Sh3dImport>::failure(Code::invalid_value,
                                       fmt::format("{}: no wall to import: each of its {} <wall> "
                                                   "elements starts and ends at the same point",
                                                   file, home.walls.size()));
  const sh3d::Placement placement{levels, z_shift_cm, wall_options.chord_tolerance, nullptr};
  out.plan.openings = sh3d::place_openings(home.items, walls, placement, out.warnings);
  out.plan.slabs = sh3d::make_slabs(home, home.rooms, levels, sh3d::z_of(z_shift_cm),
                                    options.ceilings, out.warnings);
  out.plan.rooms = sh3d::make_room_labels(home.rooms, levels);
  if (out.plan.slabs.size() > kMaxPlanObjects)
    return Result<Sh3dImport>::failure(
        Code::too_large,
        too_many_objects(file, out.plan.walls.size(), out.plan.slabs.size(), "walls and", "slabs"));
  const HomeExtent box = bounds_of(out.plan, walls);
  // The site's cell counts are integers: a home spread over more cells than any plan could
  // use (coordinates like 1e115 cm) is refused rather than overflowing them.
  const double span = std::max(box.plan.max_x - box.plan.min_x, box.plan.max_y - box.plan.min_y);
  if (!((span + 2 * options.site_margin) / options.cell_size <= kMaxSiteCellsPerSide))
    return Result<Sh3dImport>::failure(
        Code::invalid_value, fmt::format("{}: the walls span {:g} m, more than {:g} cells of {:g} "
                                         "m; check the home's coordinates",
                                         file, span, kMaxSiteCellsPerSide, options.cell_size));
  out.plan.site = make_site(box, options);
  sh3d::place_compass(home.compass, home.camera_time_ms, out.plan.site, out.warnings);
  out.plan.lights = {default_light()};
  out.plan.cameras = make_cameras(home, box, out.z_shift);
  return out;
}

Result<Sh3dImport> import_sweethome3d_file(const std::filesystem::path& path,
                                           const Sh3dImportOptions& options) {
  std::error_code error;
  if (const std::uintmax_t size = std::filesystem::file_size(path, error);
      !error && size > kMaxTextFileBytes)
    return Result<Sh3dImport>::failure(
        Code::too_large,
        fmt::format("{}: it is {} bytes; files of at most {} bytes (256 MiB) are read",
                    path.string(), size, kMaxTextFileBytes));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Result<Sh3dImport>::failure(Code::io_error,
                                       fmt::format("{}: cannot open the file", path.string()));
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad())
    return Result<Sh3dImport>::failure(Code::io_error,
                                       fmt::format("{}: cannot read the file", path.string()));
  if (!sh3d::is_zip_data(bytes) && path.extension() != ".sh3d")
    return import_sweethome3d_text(bytes, path.string(), options);
  const Result<std::string> xml = sh3d::read_home_xml_entry(path);
  if (!xml) return xml.error();
  return import_sweethome3d_text(xml.value(), path.string() + ":Home.xml", options);
}

}  // namespace roomcad
