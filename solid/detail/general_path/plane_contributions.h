// SPDX-License-Identifier: GPL-3.0-or-later
// A plane's contributions (plane_faces.h) made fewer before its boolean: equal polygons made
// one, polygons that a section makes irrelevant dropped, and the test that the plane holds no
// face at all. Each keeps the solid the plane's faces bound.
#pragma once

#include <vector>

#include "solid/detail/general_path/plane_faces.h"

namespace roomcad::detail {

/// The contributions with equal polygons of one kind (solid or hole, above, below) made one: the
/// first of them, owned by the lowest-numbered primitive among them (the owner classify picks
/// where they lie). They would only repeat each other's edges and pieces: walls drawn over one
/// another give many. O(n log n) plus the corners of polygons of one hash.
[[nodiscard]] std::vector<Contribution> without_duplicates(std::vector<Contribution> contributions);

/// The contributions without those lying in a section that makes them irrelevant: in a solid
/// section every solid polygon (solid lies above and below there whatever they say), in a hole
/// section every polygon (holes take both sides away). Where a face lies inside a solid
/// section, only holes make it and own it. Walls drawn over one another give many: a lower
/// storey's wall top inside the section of a wall across it. O(n s) box tests for s sections,
/// plus the side tests of containment where boxes meet; each polygon is tested against the
/// kept sections.
[[nodiscard]] std::vector<Contribution> without_covered(const PlaneSet& set,
                                                        std::vector<Contribution> contributions);

/// Whether the plane surely holds no face of the solid: every solid polygon with a face there
/// lies whole in a solid polygon on its other side (a section, or a face of a primitive
/// beyond), and no hole has a face there. Then solid lies on both sides of every point that
/// has solid on either (holes' sections take both sides away alike): a storey's wall tops under
/// the next storey's walls, faces inside walls drawn over one another. A shortcut: false does
/// not mean faces (a face whose middle, rounded to doubles, lies in no polygon beyond it gives
/// false before any containment test: most planes with faces). O(n^2) box tests, and the
/// predicates of containment tests where boxes meet, the polygons holding the middle first.
[[nodiscard]] bool has_no_faces(const PlaneSet& set,
                                const std::vector<Contribution>& contributions);

}  // namespace roomcad::detail
