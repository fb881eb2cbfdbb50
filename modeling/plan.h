// The plan model: walls, openings, lights and cameras on a tiled site, in metres.
//
// This is the in-memory form of ../shared/spec/plan-format.md (version 1). Every field of the
// format has a member here with the spec's default, so reading then writing loses nothing;
// fields the format does not know are kept verbatim in `extra` for the same reason.
// The model holds what was written, even when it is wrong (a negative thickness, a dangling
// wall reference): judging it is validation's job, so that edits and tools can hold a plan
// that is being repaired.
#pragma once

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

/// A field the format does not define, kept so that saving loses nothing.
/// `json` is the field's value as canonical JSON text.
struct ExtraField {
  std::string key;
  std::string json;
  friend bool operator==(const ExtraField&, const ExtraField&) = default;
};
using ExtraFields = std::vector<ExtraField>;

struct Site {
  Point2 origin{0.0, 0.0};
  std::array<std::int64_t, 2> cells{12, 8};  ///< tiles along x and y
  double cell_size = 1.0;                    ///< metres per tile side
  double max_height = 6.0;
  double tolerance = 1e-6;                   ///< join tolerance, metres
  Color floor_color{0xc8, 0xc8, 0xc8};
  ExtraFields extra;
  friend bool operator==(const Site&, const Site&) = default;
};

struct Wall {
  std::string id;
  Point2 from;
  Point2 to;
  double thickness = 0.25;
  double height = 2.8;
  double base = 0.0;
  Color color{0xe8, 0xe2, 0xd0};
  ExtraFields extra;
  friend bool operator==(const Wall&, const Wall&) = default;
};

enum class OpeningType { door, window };
enum class Hinge { left, right };
enum class Swing { in, out };

struct Opening {
  std::string id;
  OpeningType type = OpeningType::door;
  std::string wall;      ///< id of the host wall
  double offset = 0.0;   ///< start along the wall from its `from` end, metres
  double width = 0.9;
  double height = 2.1;
  double sill = 0.0;     ///< bottom above the wall's base
  Hinge hinge = Hinge::left;
  Swing swing = Swing::in;
  ExtraFields extra;
  friend bool operator==(const Opening&, const Opening&) = default;
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
  std::string id;
  LightType type = LightType::directional;
  Vec3 direction{-0.4, 0.5, -1.0};  ///< from the light into the scene
  double intensity = 1.0;
  double ambient = 0.25;            ///< in [0, 1]
  ExtraFields extra;
  friend bool operator==(const Light&, const Light&) = default;
};

enum class Projection { perspective, orthographic };

struct Camera {
  std::string id;
  Projection projection = Projection::perspective;
  Vec3 eye;
  Vec3 target;
  Vec3 up{0.0, 0.0, 1.0};
  double fov_deg = 50.0;      ///< vertical field of view (perspective)
  double view_height = 10.0;  ///< metres seen vertically (orthographic)
  ExtraFields extra;
  friend bool operator==(const Camera&, const Camera&) = default;
};

struct Plan {
  Site site;
  std::vector<Wall> walls;
  std::vector<Opening> openings;
  std::vector<Light> lights;    ///< empty: a default light is used (see default_lights)
  std::vector<Camera> cameras;  ///< empty: a camera framing the plan is used
  ExtraFields extra;            ///< unknown top-level fields
  friend bool operator==(const Plan&, const Plan&) = default;
};

/// @return the wall with this id, or nullptr. O(n).
const Wall* find_wall(const Plan& plan, std::string_view id);
/// @return the light the spec promises when a plan has none: the spec example's sun.
Light default_light();

std::string_view to_string(OpeningType t);
std::string_view to_string(Hinge h);
std::string_view to_string(Swing s);
std::string_view to_string(LightType t);
std::string_view to_string(Projection p);

}  // namespace roomcad
