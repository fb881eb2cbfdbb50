// SPDX-License-Identifier: GPL-3.0-or-later
// The meshes roomcad builds: OpenMesh polygon meshes in double precision, with the per-face
// properties every later stage (export, render, drawings) reads. All persistent properties are
// declared here and only here (STYLE rule 14); scratch properties use makeTemporaryProperty.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "mesh/cells.h"
#include "plan/plan.h"

namespace roomcad {

struct SolidTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge | OpenMesh::Attributes::Status);
};

/// A polygon mesh in metres (x east, y north, z up); faces are planar and counter-clockwise
/// seen from outside.
using SolidMesh = OpenMesh::PolyMesh_ArrayKernelT<SolidTraits>;

/// What a face is, for materials, drawings and picking.
enum class FaceKind : std::uint8_t {
  wall_face,  ///< a side of a wall (either side)
  wall_top,
  wall_bottom,
  wall_end,  ///< the end cap of a free wall end
  jamb,      ///< the vertical side of an opening
  sill,      ///< the bottom of an opening
  lintel,    ///< the top of an opening
  floor,
  door,    ///< a door leaf fixture
  window,  ///< a window pane fixture
  slab,    ///< any face of a slab (a floor or ceiling of plan format version 2)
};
std::string_view to_string(FaceKind k);

/// Names of the persistent face properties (OpenMesh property names, "rc:" prefix).
inline constexpr const char* kObjectProperty =
    "rc:object";  ///< int: index into Model::objects, -1 none
inline constexpr const char* kKindProperty = "rc:kind";    ///< FaceKind
inline constexpr const char* kColorProperty = "rc:color";  ///< Color

/// Adds the persistent face properties to a mesh (idempotent).
void add_face_properties(SolidMesh& mesh);

/// Handles of the persistent face properties.
struct FacePropertyHandles {
  OpenMesh::FPropHandleT<int> object;
  OpenMesh::FPropHandleT<FaceKind> kind;
  OpenMesh::FPropHandleT<Color> color;
};
/// @return the handles of a mesh's persistent face properties.
/// @throws std::logic_error if add_face_properties(mesh) was never called.
[[nodiscard]] FacePropertyHandles face_property_handles(const SolidMesh& mesh);

/// @return the area of a planar face in square metres (half its fan's cross product). O(its
/// corners).
[[nodiscard]] double face_area(const SolidMesh& mesh, SolidMesh::FaceHandle face);

/// The result of building a plan: one mesh per part, sharing one object table.
struct Model {
  SolidMesh walls;                   ///< the wall solid: closed, 2-manifold, outward oriented
  SolidMesh floor;                   ///< the tiled floor
  SolidMesh fixtures;                ///< door leaves and window panes
  std::vector<std::string> objects;  ///< object ids; rc:object indexes this
  bool slabs_built = true;           ///< `walls` holds the plan's slabs (false: built without them)
  Cells cells{};                     ///< rooms and portals (BuildOptions::cells), else empty
};

}  // namespace roomcad
