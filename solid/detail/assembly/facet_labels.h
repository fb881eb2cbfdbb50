// SPDX-License-Identifier: GPL-3.0-or-later
// One colour per merged facet. A boolean result's facet that spans several joined walls comes
// back triangulated when it has holes, and labelling each triangle on its own (the wall holding
// most of its corners) paints a diagonal colour boundary across the facet. The triangles of one
// facet are regrouped here and all take the facet's dominant colour. Each triangle keeps its
// own object (the wall holding most of its corners), which picking and highlighting use.
#pragma once

#include "solid/detail/assembly/face_soup.h"
#include "solid/detail/assembly/snap_soup.h"

namespace roomcad::detail {

/// Gives the triangles of each facet one colour: triangles of `soup` that share an edge and a
/// plane form a group (opening faces, sills, jambs and lintels never join one), and every
/// triangle of a group takes the colour that covers most of the group's area.
/// @param[in]     indexed the soup's polygons as vertex indices (same order and size as soup)
/// @param[in,out] soup    labelled faces; only colours change (replace in place)
/// Cost O(n) expected for n corners (hashing), plus O(g log g) per group of g triangles.
void unify_facet_labels(const IndexedSoup& indexed, FaceSoup& soup);

}  // namespace roomcad::detail
