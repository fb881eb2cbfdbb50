// SPDX-License-Identifier: GPL-3.0-or-later
// The primitives of the general build path: convex polyhedra in plane-based form
// (exact_planes.h). A wall piece is its convex footprint between its base and its top (a
// horizontal or sloped plane); an opening's hole is its convex outline in the wall's vertical
// plane between the wall's two side planes. The solid is the union of the solids minus the
// union of the holes (general_solid.h).
//
// A footprint is the intersection of the half-planes of its four sides: for a quad that is
// convex (every wall not shorter than its mitres) that is the quad; a "bow-tie", whose mitre
// lines cross inside the wall, keeps the triangle between them; a footprint with no area
// is empty. exact_wall.h's exact_footprint computes the same set for the Nef reference and the
// analytic volume.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/box.h"
#include "solid/detail/frames/slab_frames.h"
#include "solid/detail/frames/wall_frame.h"
#include "solid/detail/general_path/exact_planes.h"

namespace roomcad::detail {

/// A convex polygon in `plane`: lines[i] are planes whose negative sides hold it, vertices[i]
/// is where lines[i] and lines[i + 1] meet; counter-clockwise seen from the plane's positive side.
struct PlanePolygon {
  PlaneRef plane;
  std::vector<PlaneRef> lines;
  std::vector<XPoint> vertices;
};

/// The planes x, y, z = -M and +M around everything (M a power of two), from which sections
/// are clipped.
struct BoxPlanes {
  std::array<PlaneId, 3> low{}, high{};
};

/// @return the largest magnitude of the walls' footprint coordinates, bases and tops and of the
///         slabs' outline boxes, bottoms and tops (add_box_planes' argument). O(n).
[[nodiscard]] double largest_coordinate(std::span<const WallFrame* const> walls,
                                        std::span<const SlabFrame* const> slabs);

/// @return box planes at +-M, M the smallest power of two >= 4 * (largest |coordinate| + 1).
[[nodiscard]] BoxPlanes add_box_planes(PlaneSet& set, double largest_coordinate);

/// @return the square of the box's lines around the origin in `plane`, counter-clockwise.
[[nodiscard]] PlanePolygon box_polygon(const PlaneSet& set, const BoxPlanes& box, PlaneRef plane);

/// Keeps the part of the polygon on the negative side of `h` (zero-length edges dropped).
/// @return false if nothing of positive area is left. O(n) predicates.
bool clip_polygon(const PlaneSet& set, PlanePolygon& polygon, PlaneRef h);

/// @return the axis along which the plane's normal is largest (its 2D view drops it).
[[nodiscard]] int dominant_axis(const PlaneSet& set, PlaneId plane);

/// @return the box of the points' intervals (empty: low +inf, high -inf). O(n).
[[nodiscard]] Box3 box_of(std::span<const XPoint> points);

/// A convex polyhedron: a solid (wall piece, or a convex piece of a slab) or a hole (an
/// opening's, or a convex part of it).
struct Primitive {
  static constexpr std::size_t kNoSlab = SIZE_MAX;
  enum class Kind : std::uint8_t { solid, hole } kind = Kind::solid;
  std::size_t frame = 0;            ///< index of its wall in the walls given to the builder
  std::size_t slab = kNoSlab;       ///< for a slab's piece: index of its slab in the slabs given
  std::size_t opening = 0;          ///< Plan::openings index, for a hole
  std::vector<PlanePolygon> faces;  ///< plane: outward; counter-clockwise seen from outside
  std::vector<XPoint> vertices;
  Box3 box;
};

/// The primitives of walls and their holes, in order: each wall's piece then its holes; then
/// each slab's pieces.
/// @param[in,out] set  receives every plane used.
/// @return primitives; a wall or hole with no volume in doubles (a footprint of no area, a
///         height that rounds to 0) has none. Cost O(walls + holes + slab corners) predicates;
///         the planes are made in order, then the walls' primitives in parallel (the same
///         primitives and plane ids at any thread count). A wall whose footprint is unbounded
///         throws; where several do, the first in order.
[[nodiscard]] std::vector<Primitive> make_primitives(PlaneSet& set, const BoxPlanes& box,
                                                     const std::vector<const WallFrame*>& walls,
                                                     const std::vector<const SlabFrame*>& slabs);

/// The convex polyhedron on the negative side of every plane (outward), for shapes that are not
/// prisms: each plane's face is the box's square in it clipped by every other plane.
/// @return none if fewer than four faces have area (no volume). O(m^2) polygon clips for m
///         planes.
[[nodiscard]] std::optional<Primitive> make_convex(const PlaneSet& set, const BoxPlanes& box,
                                                   const std::vector<PlaneRef>& planes);

/// Replaces every plane id in the primitives by its group's (PlaneSet::find_equal_planes).
void use_plane_groups(std::vector<Primitive>& primitives, const std::vector<PlaneRef>& groups);

}  // namespace roomcad::detail
