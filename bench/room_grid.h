// SPDX-License-Identifier: GPL-3.0-or-later
// Generated grids of rooms for the render benchmarks, built as meshes directly (the same
// shapes build_model makes: walls with a door or a window cut out, tiled floors, leaves and
// panes), about 350 triangles per room: 10 x 10 rooms is ~35k triangles, 77 x 77 ~2.1M.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "scene_support.h"

namespace roomcad::samples {

inline constexpr double kRoom = 4.0;  // metres between wall centres
inline constexpr double kThick = 0.2;
inline constexpr double kHeight = 2.8;

/// One wall along `axis` (0: x, 1: y) from `start`, `kRoom` long, with an opening
/// [at, at + width] x [sill, top] cut out as the boxes around it.
inline void add_wall_with_opening(SolidMesh& mesh, glm::dvec2 start, int axis, double at,
                                  double width, double sill, double top, int object) {
  auto box = [&](double a0, double a1, double z0, double z1) {
    if (a1 - a0 <= 0.0 || z1 - z0 <= 0.0) return;
    const glm::dvec3 lo =
        axis == 0 ? glm::dvec3(start.x + a0, start.y, z0) : glm::dvec3(start.x, start.y + a0, z0);
    const glm::dvec3 hi = axis == 0 ? glm::dvec3(start.x + a1, start.y + kThick, z1)
                                    : glm::dvec3(start.x + kThick, start.y + a1, z1);
    test::add_box(mesh, lo, hi, object);
  };
  box(0.0, at, 0.0, kHeight);
  box(at + width, kRoom, 0.0, kHeight);
  box(at, at + width, 0.0, sill);
  box(at, at + width, top, kHeight);
}

/// A vertical quad (door leaf or pane) in the opening of a wall.
inline void add_panel(SolidMesh& mesh, glm::dvec2 start, int axis, double at, double width,
                      double z0, double z1, int object, Color color) {
  const glm::dvec2 along = axis == 0 ? glm::dvec2(1, 0) : glm::dvec2(0, 1);
  const glm::dvec2 a = start + along * at + (glm::dvec2(1, 1) - along) * (kThick / 2);
  const glm::dvec2 b = a + along * width;
  test::add_face(mesh, {{a.x, a.y, z0}, {b.x, b.y, z0}, {b.x, b.y, z1}, {a.x, a.y, z1}}, object,
                 FaceKind::window, color);
}

/// n x n rooms: south wall with a door, the other three with a window; floor in 0.5 m tiles.
inline Model make_room_grid(int n) {
  Model m;
  m.objects = {"floor"};
  const double tile = 0.5;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 o(i * kRoom, j * kRoom);
      const int id = static_cast<int>(m.objects.size());
      m.objects.push_back("room" + std::to_string(j * n + i));
      add_wall_with_opening(m.walls, o, 0, 1.5, 0.9, 0.0, 2.1, id);
      add_wall_with_opening(m.walls, o + glm::dvec2(0, kRoom - kThick), 0, 1.4, 1.2, 0.9, 2.1, id);
      add_wall_with_opening(m.walls, o, 1, 1.4, 1.2, 0.9, 2.1, id);
      add_wall_with_opening(m.walls, o + glm::dvec2(kRoom - kThick, 0), 1, 1.4, 1.2, 0.9, 2.1, id);
      add_panel(m.fixtures, o, 0, 1.5, 0.9, 0.0, 2.1, id, {120, 80, 40});
      add_panel(m.fixtures, o + glm::dvec2(0, kRoom - kThick), 0, 1.4, 1.2, 0.9, 2.1, id,
                {150, 200, 230});
      for (double y = 0; y < kRoom - 1e-9; y += tile)
        for (double x = 0; x < kRoom - 1e-9; x += tile)
          test::add_floor(m.floor, o + glm::dvec2(x, y), o + glm::dvec2(x + tile, y + tile), 0);
    }
  }
  return m;
}

}  // namespace roomcad::samples
