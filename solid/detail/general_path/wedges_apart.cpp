// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/detail/general_path/wedges_apart.h"

namespace roomcad::detail {

bool wedges_apart(const PlaneSet& set, PlaneRef plane, PlaneRef m0, PlaneRef m1, PlaneRef across,
                  bool below) {
  if (m0.id == m1.id) return false;
  const int frame = orient_normals(set, m0, plane, across) * (below ? 1 : -1);
  return frame * orient_normals(set, m0, m1, across) < 0;
}

}  // namespace roomcad::detail
