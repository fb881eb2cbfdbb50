// SPDX-License-Identifier: GPL-3.0-or-later
// The plan model: walls, openings, slabs, levels, lights and cameras on a tiled site, in metres.
//
// This is the in-memory form of the plan format (docs/plan-format.md, versions 1 and 2). Every
// field of the format has a member here with the format's default, so reading then writing
// loses nothing; fields the format does not know are kept verbatim in `extra` for the same
// reason. Which member is which field, with its unit, check and presence, is said once, in
// plan/plan_fields.h, which the reader, the writer, the edits and the checks all use.
// Version-2 members are optional (or empty) when the file does not use them.
// The model holds what was written, even when it is wrong (a negative thickness, a dangling
// wall reference): judging it is validation's job, so that edits and tools can hold a plan
// that is being repaired.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace roomcad {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

/// An sRGB colour, written `#rrggbb`.
struct Color {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Color&, const Color&) = default;
};

/// Parses `#rrggbb` (either case). @return nullopt for anything else.
std::optional<Color> parse_color(std::string_view text);
/// @return `#rrggbb` in lower case.
std::string to_string(Color c);

/// A polygon in metres (or in an opening's unit square, for `shape`): its corners in order, the
/// last joined to the first.
using Polygon = std::vector<Point2>;

/// A field the format does not define, kept so that saving loses nothing.
/// `json` is the field's value as canonical JSON text.
struct ExtraField {
  std::string key{};
  std::string json{};
  friend bool operator==(const ExtraField&, const ExtraField&) = default;
};
using ExtraFields = std::vector<ExtraField>;

/// Where a site is on the Earth (version 2's `site.location`): what the sun's position is
/// computed from.
struct GeoLocation {
  double latitude = 0.0;    ///< degrees north, [-90, 90]
  double longitude = 0.0;   ///< degrees east, [-180, 180]
  double utc_offset = 0.0;  ///< hours of the site's local time ahead of UTC, [-12, 14]
  ExtraFields extra{};
  friend bool operator==(const GeoLocation&, const GeoLocation&) = default;
};

struct Site {
  Point2 origin{0.0, 0.0};
  std::array<std::int64_t, 2> cells{12, 8};  ///< tiles along x and y
  double cell_size = 1.0;                    ///< metres per tile side
  double max_height = 6.0;
  double tolerance = 1e-6;  ///< join tolerance, metres
  Color floor_color{0xc8, 0xc8, 0xc8};
  /// Largest sagitta of the chords an arc wall is built as (version 2; absent: 0.001 m).
  std::optional<double> chord_tolerance{};
  /// Where the site is (version 2; absent: the plan has no sun of its own).
  std::optional<GeoLocation> location{};
  /// Degrees from the plan's +y axis to true north, counter-clockwise (version 2; absent: 0).
  std::optional<double> north{};
  ExtraFields extra{};
  friend bool operator==(const Site&, const Site&) = default;
};

/// The chord tolerance of a site whose file gives none (version 2's default).
inline constexpr double kDefaultChordTolerance = 0.001;

/// A storey (version 2): walls and slabs on it measure their base or top from its elevation.
struct Level {
  std::string id{};
  double elevation = 0.0;  ///< z of the level's floor, metres
  double height = 2.8;     ///< floor-to-floor height; the height of its walls that give none
  ExtraFields extra{};
  friend bool operator==(const Level&, const Level&) = default;
};

struct Wall {
  std::string id{};
  std::string level{};  ///< id of its level (version 2), empty for none
  Point2 from{};
  Point2 to{};
  double thickness = 0.25;
  /// Height at `from`. A wall of a level that gives no height takes the level's when read.
  double height = 2.8;
  double base = 0.0;  ///< above its level's elevation, or above z = 0 without a level
  /// Height at `to` (version 2): the top is the plane through the top edge. Absent: `height`.
  std::optional<double> height_at_end{};
  /// Degrees the centre line turns from `from` to `to` (version 2): an arc, built as chords
  /// within the site's chord tolerance. Absent: straight.
  std::optional<double> arc_extent{};
  Color color{0xe8, 0xe2, 0xd0};
  ExtraFields extra{};
  friend bool operator==(const Wall&, const Wall&) = default;
};

/// @return the highest top of wall `w` above its base: its height, or the higher end of a
///         sloped top. O(1).
[[nodiscard]] inline double highest_height(const Wall& w) {
  return std::max(w.height, w.height_at_end.value_or(w.height));
}

enum class OpeningType { door, window };
enum class Hinge { left, right };
enum class Swing { in, out };

struct Opening {
  std::string id{};
  OpeningType type = OpeningType::door;
  std::string wall{};   ///< id of the host wall
  double offset = 0.0;  ///< start along the wall from its `from` end, metres
  double width = 0.9;
  double height = 2.1;
  double sill = 0.0;  ///< bottom above the wall's base
  Hinge hinge = Hinge::left;
  Swing swing = Swing::in;
  /// The hole's outline in the unit square of its rectangle (version 2), counter-clockwise;
  /// empty: the whole rectangle.
  Polygon shape{};
  ExtraFields extra{};
  friend bool operator==(const Opening&, const Opening&) = default;
};

/// A floor, ceiling or landing (version 2): `outline` minus `holes`, from top - thickness up
/// to top (top measured from its level's elevation, or from z = 0 without a level).
struct Slab {
  std::string id{};
  std::string level{};           ///< id of its level, empty for none
  Polygon outline{};             ///< counter-clockwise
  std::vector<Polygon> holes{};  ///< stair wells: strictly inside the outline, disjoint
  double top = 0.0;
  double thickness = 0.2;
  Color color{0xd8, 0xd2, 0xc4};
  ExtraFields extra{};
  friend bool operator==(const Slab&, const Slab&) = default;
};

/// A name for the room around a point (roomcad's own field, `rooms[]`): the room that the
/// walls of `level` close around `at` is called `name` ("Kitchen", "Bath"). Names decide
/// which rooms a person stays in (room_without_window asks a window only of those).
struct RoomLabel {
  std::string id{};
  std::string level{};  ///< id of its level, empty for none
  Point2 at{};          ///< a point inside the room
  std::string name{};
  ExtraFields extra{};
  friend bool operator==(const RoomLabel&, const RoomLabel&) = default;
};

/// A neighbouring building, tree or fence (version 2's `obstructions[]`): the prism over
/// `outline` from `base` up to `base + height`, in absolute z. Not part of the plan's solid; it
/// casts shadows and blocks sunlight.
struct Obstruction {
  std::string id{};
  Polygon outline{};  ///< counter-clockwise
  double base = 0.0;
  double height = 10.0;
  ExtraFields extra{};
  friend bool operator==(const Obstruction&, const Obstruction&) = default;
};

/// The defaults the spec gives each opening type (width, height, sill).
struct OpeningDefaults {
  double width;
  double height;
  double sill;
};
OpeningDefaults opening_defaults(OpeningType type);

enum class LightType { directional };

struct Light {
  std::string id{};
  LightType type = LightType::directional;
  Vec3 direction{-0.4, 0.5, -1.0};  ///< from the light into the scene
  double intensity = 1.0;
  double ambient = 0.25;  ///< in [0, 1]
  ExtraFields extra{};
  friend bool operator==(const Light&, const Light&) = default;
};

enum class Projection { perspective, orthographic };

struct Camera {
  std::string id{};
  Projection projection = Projection::perspective;
  Vec3 eye{};
  Vec3 target{};
  Vec3 up{0.0, 0.0, 1.0};
  double fov_deg = 50.0;      ///< vertical field of view (perspective)
  double view_height = 10.0;  ///< metres seen vertically (orthographic)
  ExtraFields extra{};
  friend bool operator==(const Camera&, const Camera&) = default;
};

struct Plan {
  Site site;
  std::vector<Level> levels{};  ///< version 2
  std::vector<Wall> walls{};
  std::vector<Opening> openings{};
  std::vector<Slab> slabs{};                ///< version 2
  std::vector<RoomLabel> rooms{};           ///< names of rooms
  std::vector<Obstruction> obstructions{};  ///< version 2
  std::vector<Light> lights{};    ///< empty: a default light is used (render: default_light)
  std::vector<Camera> cameras{};  ///< empty: a camera framing the plan is used
  ExtraFields extra{};            ///< unknown top-level fields
  friend bool operator==(const Plan&, const Plan&) = default;
};

/// @return the wall with this id, or nullptr. O(n).
const Wall* find_wall(const Plan& plan, std::string_view id);
/// @return the light the spec promises when a plan has none: the spec example's sun.
Light default_light();

/// Every value of each enum of the format, in the order the format lists them: what readers,
/// `set` and messages accept and name (with to_string).
template <class E>
struct EnumValues;
template <>
struct EnumValues<OpeningType> {
  static constexpr OpeningType all[] = {OpeningType::door, OpeningType::window};
};
template <>
struct EnumValues<Hinge> {
  static constexpr Hinge all[] = {Hinge::left, Hinge::right};
};
template <>
struct EnumValues<Swing> {
  static constexpr Swing all[] = {Swing::in, Swing::out};
};
template <>
struct EnumValues<LightType> {
  static constexpr LightType all[] = {LightType::directional};
};
template <>
struct EnumValues<Projection> {
  static constexpr Projection all[] = {Projection::perspective, Projection::orthographic};
};

std::string_view to_string(OpeningType t);
std::string_view to_string(Hinge h);
std::string_view to_string(Swing s);
std::string_view to_string(LightType t);
std::string_view to_string(Projection p);

}  // namespace roomcad
