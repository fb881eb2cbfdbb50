// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry of an IFC file as the importer reads it (import/ifc_import.h): placements
// resolved through IfcLocalPlacement chains, the length unit, and each product's 'Body' as
// extruded prisms and its 'Axis' as a segment, all in world coordinates of file units.
// Anything the reader does not follow is returned as a sentence for a warning, never dropped.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/step_file.h"

namespace roomcad::ifc {

struct Vec {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

/// An affine map with orthonormal (or, in mapped items, scaled) axes: p -> origin + sum p_i
/// axes[i].
struct Transform {
  std::array<Vec, 3> axes{Vec{1, 0, 0}, Vec{0, 1, 0}, Vec{0, 0, 1}};
  Vec origin{};
  [[nodiscard]] Vec apply(Vec p) const;
  [[nodiscard]] Vec rotate(Vec v) const;  ///< the linear part only
  /// @return this map after `inner`: x -> this(inner(x)).
  [[nodiscard]] Transform after(const Transform& inner) const;
};

/// A half-space a clipping (IfcBooleanClippingResult) removes from a body, world coordinates:
/// the points q with dot(q - point, removed) > 0, and of those, when `boundary` is not empty
/// (IfcPolygonalBoundedHalfSpace), only the ones whose projection along `boundary_axis` falls
/// inside that polygon.
struct Clip {
  Vec point{};
  Vec removed{};  ///< unit normal of the plane, pointing into the removed side
  std::vector<Vec> boundary{};
  Vec boundary_axis{};
  /// @return true if the clip removes world point q (file units).
  [[nodiscard]] bool removes(Vec q) const;
  /// @return true if q lies within the boundary's prism (always, for an unbounded clip).
  [[nodiscard]] bool bounds(Vec q) const;
  /// @return the fractions t in (0, 1) where the segment a + t (b - a) crosses the side of the
  ///   boundary's prism (none for an unbounded clip). O(boundary).
  [[nodiscard]] std::vector<double> crossings(Vec a, Vec b) const;
};

/// A planar profile (outer ring and holes, world coordinates) swept along `sweep` (its length is
/// the depth), less the half-spaces its clippings remove.
struct Prism {
  std::vector<Vec> outer{};
  std::vector<std::vector<Vec>> holes{};
  Vec sweep{};
  bool rectangle = false;  ///< the profile was an IfcRectangleProfileDef
  std::vector<Clip> clips{};
  /// Largest distance, metres, from an arc of the profile to the chords that stand for it.
  double chord_error = 0.0;
};

/// A straight or circular centre line ('Axis'), world coordinates of file units.
struct AxisCurve {
  Vec from{};
  Vec to{};
  /// Degrees turned from `from` to `to`, counter-clockwise positive (IfcTrimmedCurve of an
  /// IfcCircle); absent: straight.
  std::optional<double> arc_extent{};
  Vec centre{};
  double radius = 0.0;
};

/// The largest distance, metres, between an arc and the chords it is read as.
inline constexpr double kChordSagitta = 0.001;

/// Reads placements and shapes of one file; caches placements.
class Geometry {
 public:
  explicit Geometry(const step::File& file)
      : file_(file), sagitta_(kChordSagitta / metres_per_unit()) {}

  /// @return the instance a value refers to, or nullptr (not a reference, or dangling).
  [[nodiscard]] const step::Instance* get(const step::Value& v) const;
  /// @return the instance's parameter `i`, or a null value when it has fewer.
  [[nodiscard]] static const step::Value& param(const step::Instance& e, std::size_t i);

  /// @return metres per length unit of the file (IfcUnitAssignment's LENGTHUNIT; 1 if none).
  [[nodiscard]] double metres_per_unit() const;
  /// @return the world transform of an ObjectPlacement (IfcLocalPlacement chains; identity for
  ///   anything else). O(chain length) the first time, O(1) after.
  [[nodiscard]] Transform placement(const step::Value& object_placement);
  /// @return the product's 'Body' as prisms in world coordinates; each item that is not an
  ///   extrusion of a supported profile adds a sentence to `problems` (a boolean result that is
  ///   not a clipping by half-spaces adds one and keeps its first operand); half-spaces clipped
  ///   off are the prisms' `clips`. Arcs of profiles are chords within kChordSagitta.
  [[nodiscard]] std::vector<Prism> body(const step::Instance& product,
                                        std::vector<std::string>& problems);
  /// @return the product's 'Axis' in world coordinates, if it has one: the ends of a polyline
  ///   or indexed poly-curve, or an arc (a trimmed IfcCircle).
  [[nodiscard]] std::optional<AxisCurve> axis(const step::Instance& product);
  /// @return every point of the product's 'Body' in world coordinates (the vertices of
  ///   extrusions and face-based solids, mapped items followed), for an extent. O(body size).
  [[nodiscard]] std::vector<Vec> body_points(const step::Instance& product);

 private:
  const step::File& file_;
  std::unordered_map<std::uint32_t, Transform> placements_;
  int depth_ = 0;              ///< guards placement cycles
  double sagitta_;             ///< kChordSagitta in file units
  mutable bool arcs_ = false;  ///< an arc was read as chords since the last profile began

  [[nodiscard]] const step::Instance* representation(const step::Instance& product,
                                                     const char* identifier) const;
  void add_item(const step::Instance& item, const Transform& to_world, std::vector<Prism>& out,
                std::vector<std::string>& problems, int depth);
  [[nodiscard]] std::optional<Prism> profile(const step::Instance& p, const Transform& to_plane,
                                             std::vector<std::string>& problems) const;
  [[nodiscard]] std::optional<std::vector<Vec>> curve(const step::Instance& c,
                                                      const Transform& to_plane,
                                                      std::vector<std::string>& problems) const;
  /// Appends the points of an open or closed curve, arcs as chords; @return false (with a
  /// problem) for a curve it does not read.
  bool chain(const step::Instance& c, const Transform& to_plane, std::vector<Vec>& out,
             std::vector<std::string>& problems, int depth) const;
  bool trimmed_circle(const step::Instance& c, const Transform& to_plane, std::vector<Vec>& out,
                      std::vector<std::string>& problems) const;
  void arc_through(Vec a, Vec m, Vec b, const Transform& to_plane, std::vector<Vec>& out) const;
  [[nodiscard]] std::optional<Clip> half_space(const step::Instance& h,
                                               const Transform& to_world) const;
  void add_points(const step::Instance& item, const Transform& to_world, std::vector<Vec>& out,
                  int depth);
  [[nodiscard]] std::optional<Vec> point(const step::Value& v) const;
  [[nodiscard]] std::optional<Vec> direction(const step::Value& v) const;
  [[nodiscard]] Transform axis_placement(const step::Value& v) const;
  [[nodiscard]] Transform operator_3d(const step::Instance& op) const;
  [[nodiscard]] double radians_per_angle_unit() const;
  /// @return the unit of `kind` ("LENGTHUNIT") of the file's IfcUnitAssignment, if any.
  [[nodiscard]] const step::Instance* unit_of(const char* kind) const;
  /// @return an IfcConversionBasedUnit's factor (times 1e-3 over a millimetre), if valid.
  [[nodiscard]] std::optional<double> conversion_factor(const step::Instance& unit) const;
};

/// @return "#id TYPE", as warnings name an entity.
[[nodiscard]] std::string name_of(const step::Instance& e);

}  // namespace roomcad::ifc
