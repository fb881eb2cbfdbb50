// SPDX-License-Identifier: GPL-3.0-or-later
// Areas of a solid's faces by kind, for tests that compare the solids of two paths face kind
// by face kind (the volume error rounding allows is solid/wall_check.h's volume_tolerance).
#pragma once

#include <map>

#include "mesh/solid_mesh.h"

namespace roomcad::test {

/// Area of the faces of each kind.
std::map<FaceKind, double> area_by_kind(const SolidMesh& mesh);

}  // namespace roomcad::test
