// SPDX-License-Identifier: GPL-3.0-or-later
// The parts of a Sweet Home 3D `Home.xml` that roomcad imports, already in roomcad's frame.
//
// Sweet Home 3D writes centimetres in screen coordinates (x right, y down, angles clockwise in
// radians). Parsing converts once: lengths to metres, y negated, angles made counter-clockwise,
// so that everything downstream works in the plan format's frame (x east, y north, z up).
// Heights of levels and walls stay in centimetres: sh3d::z_of places them on the z axis.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad::sh3d {

/// A storey: walls and items on it stand on `elevation_cm`.
struct Level {
  std::string id;
  std::string name;
  double elevation_cm = 0.0;
  double floor_thickness_cm = 0.0;
  double height_cm = 0.0;
};

/// A `<wall>`: a straight box, or a circular arc when `arc_extent` is set.
struct WallRecord {
  std::string id;
  std::string level;          ///< level id, empty for a home without levels
  std::string wall_at_start;  ///< id of the wall joined at `start`, may be empty
  std::string wall_at_end;
  Point2 start;
  Point2 end;
  double thickness = 0.0;
  std::optional<double> height_cm;         ///< absent: the home's default wall height
  std::optional<double> height_at_end_cm;  ///< a sloped top when it differs from `height_cm`
  std::optional<double> arc_extent;        ///< radians, positive bulges to the left of start->end
  std::optional<Color> color;              ///< from leftSideColor (else rightSideColor)
};

/// A `<doorOrWindow>` (anywhere in the tree, groups included). `centre` is the footprint's
/// centre; `angle` turns the footprint's width axis from +x, counter-clockwise.
struct ItemRecord {
  std::string id;
  std::string name;
  std::string catalog_id;
  std::string level;
  Point2 centre;
  double angle = 0.0;
  double width = 0.0;
  double depth = 0.0;
  double height = 0.0;
  double elevation = 0.0;     ///< bottom above the level's elevation
  bool mirrored = false;      ///< the model is drawn mirrored (its hinge swaps sides)
  bool has_sash = false;      ///< it has a `<sash>` (a leaf that opens toward its front)
  bool sash_on_left = true;   ///< its first `<sash>` turns about the left half of its width
  std::string cut_out_shape;  ///< SVG path in the unit square, empty if absent
  // The part of the footprint cut in the wall, as fractions of width and height (DTD defaults).
  double wall_width = 1.0;
  double wall_left = 0.0;
  double wall_height = 1.0;
  double wall_top = 0.0;
};

/// A `<room>`: a floor (and its ceiling) drawn on a level, its points in roomcad's frame, in
/// the order drawn (either way round).
struct RoomRecord {
  std::string id;
  std::string name;
  std::string level;
  std::vector<Point2> points;
  bool floor_visible = true;
  bool ceiling_visible = true;
  std::optional<Color> floor_color;
  std::optional<Color> ceiling_color;
};

/// A `<camera>` or `<observerCamera>` child of `<home>`: the eye and the view direction.
struct CameraRecord {
  std::string kind;  ///< its `attribute`: observerCamera, topCamera or storedCamera
  std::string name;
  Vec3 eye;
  Vec3 direction;            ///< unit view direction in roomcad's frame
  double field_of_view = 0;  ///< horizontal, radians
};

/// The `<compass>`: where the home is, in radians, and which way north is.
struct CompassRecord {
  double latitude = 0.0;         ///< radians north
  double longitude = 0.0;        ///< radians east
  double north_direction = 0.0;  ///< radians clockwise on screen from the plan's up to north
  std::string time_zone;         ///< a zone name, "Europe/Paris"
};

struct Home {
  std::optional<double> wall_height_cm;  ///< the home's default wall height
  std::optional<CompassRecord> compass;
  std::optional<std::int64_t> camera_time_ms;  ///< the observer camera's `time`: the sun shown
  std::vector<Level> levels;
  std::vector<WallRecord> walls;
  std::vector<ItemRecord> items;
  std::vector<RoomRecord> rooms;
  std::vector<CameraRecord> cameras;
};

/// Parses the text of a `Home.xml`. `file` names the source in error messages.
/// @return the home, or an error naming the file, the element (by id), the attribute and its
///   value: malformed XML, a root that is not `<home>`, a missing required attribute, a number
///   that does not parse or is not finite, a level reference to no level. O(n) in the text.
[[nodiscard]] Result<Home> parse_home_xml(std::string_view xml, std::string_view file);

}  // namespace roomcad::sh3d
