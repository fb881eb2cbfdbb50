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

/// A planar profile (outer ring and holes, world coordinates) swept along `sweep` (its length is
/// the depth).
struct Prism {
  std::vector<Vec> outer{};
  std::vector<std::vector<Vec>> holes{};
  Vec sweep{};
  bool rectangle = false;  ///< the profile was an IfcRectangleProfileDef
};

/// Reads placements and shapes of one file; caches placements.
class Geometry {
 public:
  explicit Geometry(const step::File& file) : file_(file) {}

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
  ///   extrusion of a supported profile adds a sentence to `problems` (a clipping adds one and
  ///   keeps its first operand).
  [[nodiscard]] std::vector<Prism> body(const step::Instance& product,
                                        std::vector<std::string>& problems);
  /// @return the end points of the product's 'Axis' polyline in world coordinates, if it has one.
  [[nodiscard]] std::optional<std::array<Vec, 2>> axis(const step::Instance& product);

 private:
  const step::File& file_;
  std::unordered_map<std::uint32_t, Transform> placements_;
  int depth_ = 0;  ///< guards placement cycles

  [[nodiscard]] const step::Instance* representation(const step::Instance& product,
                                                     const char* identifier) const;
  void add_item(const step::Instance& item, const Transform& to_world, std::vector<Prism>& out,
                std::vector<std::string>& problems, int depth);
  [[nodiscard]] std::optional<Prism> profile(const step::Instance& p, const Transform& to_plane,
                                             std::vector<std::string>& problems) const;
  [[nodiscard]] std::optional<std::vector<Vec>> curve(const step::Instance& c,
                                                      const Transform& to_plane,
                                                      std::vector<std::string>& problems) const;
  [[nodiscard]] std::optional<Vec> point(const step::Value& v) const;
  [[nodiscard]] std::optional<Vec> direction(const step::Value& v) const;
  [[nodiscard]] Transform axis_placement(const step::Value& v) const;
  [[nodiscard]] Transform operator_3d(const step::Instance& op) const;
};

/// @return "#id TYPE", as warnings name an entity.
[[nodiscard]] std::string name_of(const step::Instance& e);

}  // namespace roomcad::ifc
