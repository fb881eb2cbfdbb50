// SPDX-License-Identifier: GPL-3.0-or-later
// What a wall solid written in doubles can be held to: areas by face kind, and the volume
// error that rounding its vertices to doubles allows, for tests that compare a built solid
// with its analytic volume.
#pragma once

#include <map>

#include "modeling/solid_mesh.h"

namespace roomcad::test {

/// Area of the faces of each kind.
std::map<FaceKind, double> area_by_kind(const SolidMesh& mesh);

/// How far a mesh written in doubles can be from the exact solid it stands for: one ulp of its
/// largest coordinate (each vertex is off by at most half an ulp in each of x, y, z). Near the
/// origin this is ~1e-15 m; at 1e7 m it is 1.9e-9 m, which on walls 1e-4 m thick is 2e-5 of
/// the volume: no output in doubles can do better there. O(vertices).
double vertex_rounding(const SolidMesh& mesh);

/// The volume error the mesh's doubles allow: 1e-9 relative, plus its surface area times
/// vertex_rounding (moving every vertex by d changes the volume by at most area x d).
double volume_tolerance(const SolidMesh& mesh, double volume);

}  // namespace roomcad::test
