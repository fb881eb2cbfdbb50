// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_home.h"

#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "io/utf8_text.h"

namespace roomcad::sh3d {
namespace {

constexpr double kCm = 0.01;  // Sweet Home 3D lengths are centimetres

/// Reads attributes of one element; the first problem is kept as the error to report, so a
/// whole element can be read without checking after every attribute.
class AttributeReader {
 public:
  AttributeReader(pugi::xml_node node, std::string_view file, std::string* error)
      : node_(node), file_(file), error_(error) {}

  /// An attribute's text. XML that is not well-formed UTF-8 is no XML at all (XML 1.0, 4.3.3):
  /// such an attribute is an error, so no ill-formed byte reaches a plan.
  std::string text(const char* name, bool required = false) {
    const pugi::xml_attribute a = node_.attribute(name);
    if (!a && required) fail(name, "is missing", "");
    const std::string_view value = a.value();
    if (const std::optional<std::size_t> at = first_ill_formed_utf8(value)) {
      fail(name,
           fmt::format("is not UTF-8 (byte {} is 0x{:02X})", *at + 1,
                       static_cast<unsigned char>(value[*at])),
           value);
      return {};
    }
    return std::string(value);
  }

  std::optional<double> optional_number(const char* name) {
    const pugi::xml_attribute a = node_.attribute(name);
    if (!a) return std::nullopt;
    const std::string_view v = a.value();
    double value = 0.0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(value)) {
      fail(name, "is not a finite number", v);
      return std::nullopt;
    }
    return value;
  }

  double number(const char* name, std::optional<double> fallback = std::nullopt) {
    const std::optional<double> v = optional_number(name);
    if (v) return *v;
    if (!fallback && node_.attribute(name).empty()) fail(name, "is missing", "");
    return fallback.value_or(0.0);
  }

  double length(const char* name, std::optional<double> fallback = std::nullopt) {
    return number(name, fallback) * kCm;
  }

  double coordinate(const char* name) {
    const double metres = length(name);
    return std::abs(metres) < 1e-9 ? 0.0 : metres;
  }

  /// A point of the plan: x right and y down in centimetres, to x east and y north in metres.
  /// Sweet Home 3D leaves float noise such as 6.1e-14 cm where it means 0: magnitudes under a
  /// nanometre are read as 0 (and the flip of y = 0 gives 0, not -0).
  Point2 point(const char* x, const char* y) { return {coordinate(x), 0.0 - coordinate(y)}; }

 private:
  void fail(const char* name, std::string_view what, std::string_view value) {
    if (!error_->empty()) return;
    const std::string id = printable_utf8(node_.attribute("id").value());
    *error_ = fmt::format("{}: <{}{}> attribute '{}' {}{}", file_, printable_utf8(node_.name()),
                          id.empty() ? "" : fmt::format(" id='{}'", id), name, what,
                          value.empty() ? "" : fmt::format(": '{}'", printable_utf8(value)));
  }

  pugi::xml_node node_;
  std::string_view file_;
  std::string* error_;
};

/// Sweet Home 3D colours are ARGB hex (`FFCFB1A5`); the alpha byte is dropped.
std::optional<Color> parse_argb(std::string_view text) {
  if (text.size() != 8) return std::nullopt;
  return parse_color(fmt::format("#{}", text.substr(2)));
}

Level read_level(AttributeReader& r) {
  return Level{.id = r.text("id", true),
               .name = r.text("name", true),
               .elevation_cm = r.number("elevation"),
               .floor_thickness_cm = r.number("floorThickness", 0.0),
               .height_cm = r.number("height", 0.0)};
}

WallRecord read_wall(AttributeReader& r) {
  WallRecord w;
  w.id = r.text("id", true);
  w.level = r.text("level");
  w.wall_at_start = r.text("wallAtStart");
  w.wall_at_end = r.text("wallAtEnd");
  w.start = r.point("xStart", "yStart");
  w.end = r.point("xEnd", "yEnd");
  w.thickness = r.length("thickness");
  w.height_cm = r.optional_number("height");
  w.height_at_end_cm = r.optional_number("heightAtEnd");
  // Positive extents bulge to the right of start->end on screen (y down), which is the left
  // once y points up: the sign carries over unchanged.
  w.arc_extent = r.optional_number("arcExtent");
  w.color = parse_argb(r.text("leftSideColor"));
  if (!w.color) w.color = parse_argb(r.text("rightSideColor"));
  return w;
}

ItemRecord read_item(AttributeReader& r) {
  return ItemRecord{.id = r.text("id"),
                    .name = r.text("name"),
                    .catalog_id = r.text("catalogId"),
                    .level = r.text("level"),
                    .centre = r.point("x", "y"),
                    .angle = -r.number("angle", 0.0),  // clockwise on screen -> counter-clockwise
                    .width = r.length("width"),
                    .depth = r.length("depth"),
                    .height = r.length("height"),
                    .elevation = r.length("elevation", 0.0),
                    .mirrored = r.text("modelMirrored") == "true",
                    .cut_out_shape = r.text("cutOutShape"),
                    .wall_width = r.number("wallWidth", 1.0),
                    .wall_left = r.number("wallLeft", 0.0),
                    .wall_height = r.number("wallHeight", 1.0),
                    .wall_top = r.number("wallTop", 0.0)};
}

RoomRecord read_room(pugi::xml_node node, AttributeReader& r, std::string_view file,
                     std::string* error) {
  RoomRecord room{.id = r.text("id"),
                  .name = r.text("name"),
                  .level = r.text("level"),
                  .points = {},
                  .floor_visible = r.text("floorVisible") != "false",
                  .ceiling_visible = r.text("ceilingVisible") != "false",
                  .floor_color = parse_argb(r.text("floorColor")),
                  .ceiling_color = parse_argb(r.text("ceilingColor"))};
  for (pugi::xml_node point : node.children("point")) {
    AttributeReader p(point, file, error);
    room.points.push_back(p.point("x", "y"));
  }
  return room;
}

/// Sweet Home 3D's camera looks along (-sin yaw, cos yaw) on screen (y down), tilted down by
/// `pitch`; on screen y is negated, which gives (-sin yaw, -cos yaw) in roomcad's frame.
CameraRecord read_camera(AttributeReader& r) {
  CameraRecord c;
  c.kind = r.text("attribute");
  c.name = r.text("name");
  const Point2 xy = r.point("x", "y");
  c.eye = {xy.x, xy.y, r.length("z")};
  const double yaw = r.number("yaw");
  const double pitch = r.number("pitch");
  c.direction = {-std::sin(yaw) * std::cos(pitch), -std::cos(yaw) * std::cos(pitch),
                 -std::sin(pitch)};
  c.field_of_view = r.number("fieldOfView");
  return c;
}

/// A `<compass>` with its place; nothing without latitude and longitude (the DTD's defaults
/// are the author's locale, not the home's).
std::optional<CompassRecord> read_compass(AttributeReader& r) {
  const std::optional<double> latitude = r.optional_number("latitude");
  const std::optional<double> longitude = r.optional_number("longitude");
  if (!latitude || !longitude) return std::nullopt;
  return CompassRecord{*latitude, *longitude, r.number("northDirection", 0.0), r.text("timeZone")};
}

/// Every `<doorOrWindow>` below `node`, in document order (groups nest them).
void collect_items(pugi::xml_node node, std::string_view file, std::string* error,
                   std::vector<ItemRecord>& items) {
  for (pugi::xml_node child : node.children()) {
    if (std::string_view(child.name()) == "doorOrWindow") {
      AttributeReader r(child, file, error);
      items.push_back(read_item(r));
      if (const pugi::xml_node sash = child.child("sash")) {
        AttributeReader s(sash, file, error);
        items.back().has_sash = true;
        items.back().sash_on_left = s.number("xAxis") < 0.5;  // a fraction of the width
      }
    } else if (std::string_view(child.name()) == "furnitureGroup") {
      collect_items(child, file, error, items);
    }
  }
}

/// @return an error naming the first wall or item that refers to a level the home lacks.
std::string check_level_references(const Home& home, std::string_view file) {
  std::set<std::string, std::less<>> ids;
  for (const Level& l : home.levels) ids.insert(l.id);
  auto unknown = [&](const std::string& level) { return !level.empty() && !ids.contains(level); };
  for (const WallRecord& w : home.walls)
    if (unknown(w.level))
      return fmt::format("{}: <wall id='{}'> attribute 'level' names no <level>: '{}'", file, w.id,
                         w.level);
  for (const ItemRecord& i : home.items)
    if (unknown(i.level))
      return fmt::format("{}: <doorOrWindow id='{}'> attribute 'level' names no <level>: '{}'",
                         file, i.id, i.level);
  for (const RoomRecord& r : home.rooms)
    if (unknown(r.level))
      return fmt::format("{}: <room id='{}'> attribute 'level' names no <level>: '{}'", file, r.id,
                         r.level);
  return {};
}

}  // namespace

Result<Home> parse_home_xml(std::string_view xml, std::string_view file) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size());
  if (!parsed)
    return Result<Home>::failure(
        Code::parse_error,
        fmt::format("{}: malformed XML at byte {}: {}", file, parsed.offset, parsed.description()));
  const pugi::xml_node root = doc.document_element();
  if (std::string_view(root.name()) != "home")
    return Result<Home>::failure(
        Code::parse_error,
        fmt::format("{}: not a Sweet Home 3D Home.xml: the root element is <{}>, not <home>", file,
                    printable_utf8(root.name())));

  Home home;
  std::string error;
  AttributeReader home_reader(root, file, &error);
  home.wall_height_cm = home_reader.optional_number("wallHeight");
  for (pugi::xml_node child : root.children()) {
    const std::string_view name = child.name();
    AttributeReader r(child, file, &error);
    if (name == "level") home.levels.push_back(read_level(r));
    else if (name == "wall") home.walls.push_back(read_wall(r));
    else if (name == "room") home.rooms.push_back(read_room(child, r, file, &error));
    else if (name == "camera" || name == "observerCamera") home.cameras.push_back(read_camera(r));
    else if (name == "compass") home.compass = read_compass(r);
    if (name == "observerCamera" && r.text("attribute") == "observerCamera")
      if (const std::optional<double> t = r.optional_number("time"); t && std::fabs(*t) < 1e17)
        home.camera_time_ms = static_cast<std::int64_t>(*t);
  }
  collect_items(root, file, &error, home.items);
  if (error.empty()) error = check_level_references(home, file);
  if (!error.empty()) return Result<Home>::failure(Code::parse_error, std::move(error));
  return home;
}

}  // namespace roomcad::sh3d
