// SPDX-License-Identifier: GPL-3.0-or-later
// The cells and portals build_model finds (mesh/cells.h): rooms of a grid, storeys of a tower
// closed by their slabs but for the stair well, windows opening onto the outside.
#include <gtest/gtest.h>

#include <algorithm>

#include "solid/build_model.h"
#include "testing/tower_plan.h"

namespace roomcad {
namespace {

TEST(FindCells, EveryRoomOfAGridIsACellWithItsDoorsAndWindows) {
  const Plan plan = samples::make_grid_plan({.n = 3});
  const Model model = build_model(plan, BuildOptions{.cells = true});
  const Cells& cells = model.cells;
  ASSERT_EQ(cells.cells.size(), 9u);
  for (const Cell& c : cells.cells) {
    EXPECT_EQ(c.floor_z, 0.0);
    EXPECT_EQ(c.top_z, 2.8);
    EXPECT_TRUE(c.open_top && c.top_outside);  // no slab, nothing above
    EXPECT_TRUE(c.open_bottom && c.bottom_outside);
    EXPECT_TRUE(c.islands.empty());
    EXPECT_NEAR(c.bounds.high[0] - c.bounds.low[0], 4.0 - 0.2 + 2e-3, 1e-9);  // between faces
  }
  // 12 inner walls with a door between two rooms, 12 outer ones with three windows each
  ASSERT_EQ(cells.portals.size(), 12u + 36u);
  std::size_t doors = 0;
  for (const Portal& p : cells.portals) {
    if (p.cells.size() == 2) {
      ++doors;
      EXPECT_FALSE(p.to_outside);
    } else {
      EXPECT_EQ(p.cells.size(), 1u);
      EXPECT_TRUE(p.to_outside);
    }
  }
  EXPECT_EQ(doors, 12u);
  EXPECT_TRUE(find_model_cells(plan, Parts{.walls = false}).empty());
}

TEST(FindCells, SlabsCloseAStoreyButForItsStairWell) {
  const Plan plan = samples::make_tower_plan({.storey = {.n = 2}, .storeys = 2});
  const Cells cells = find_model_cells(plan);
  ASSERT_EQ(cells.cells.size(), 8u);
  ASSERT_TRUE(cells.uses_slabs);
  std::size_t lower = 0, open_tops = 0, open_bottoms = 0;
  for (const Cell& c : cells.cells) {
    if (c.floor_z < 1.0) {
      ++lower;
      EXPECT_FALSE(c.open_bottom);  // the ground slab covers every room
      open_tops += c.open_top;      // the floor above has a stair well in one room
      // between the storeys lies a slab's thickness with no wall: the well opens onto it
      EXPECT_TRUE(!c.open_top || c.top_outside);
    } else {
      open_bottoms += c.open_bottom;
      EXPECT_TRUE(c.open_top);  // no roof
    }
  }
  EXPECT_EQ(lower, 4u);
  EXPECT_EQ(open_tops, 1u);
  EXPECT_EQ(open_bottoms, 1u);
  // without the slabs nothing closes
  const Cells bare = find_model_cells(plan, Parts{.slabs = false});
  EXPECT_FALSE(bare.uses_slabs);
  EXPECT_TRUE(std::all_of(bare.cells.begin(), bare.cells.end(),
                          [](const Cell& c) { return c.open_top && c.open_bottom; }));
}

// Walls standing on walls make bands of heights stacked on each other: an open floor over four
// rooms (only the outer walls go on up) is one cell over them, reached through their tops.
TEST(FindCells, CellsOfStackedBandsReachEachOtherThroughTheirTops) {
  Plan plan = samples::make_grid_plan({.n = 2});
  const std::size_t ground = plan.walls.size();
  for (std::size_t i = 0; i < ground; ++i) {
    const Wall& w = plan.walls[i];
    const bool outer = (w.from.x == w.to.x && (w.from.x == 0.0 || w.from.x == 8.0)) ||
                       (w.from.y == w.to.y && (w.from.y == 0.0 || w.from.y == 8.0));
    if (!outer) continue;
    Wall up = w;
    up.id += "-up";
    up.base = w.height;
    plan.walls.push_back(up);
  }
  plan.site.max_height = 6.0;
  const Cells cells = find_model_cells(plan);
  ASSERT_EQ(cells.cells.size(), 5u);
  std::size_t rooms = 0;
  for (std::size_t k = 0; k < cells.cells.size(); ++k) {
    const Cell& c = cells.cells[k];
    if (c.floor_z == 0.0) {
      ++rooms;
      EXPECT_EQ(c.top_z, 2.8);
      ASSERT_EQ(c.cells_above.size(), 1u);
      EXPECT_FALSE(c.top_outside);
      const Cell& floor = cells.cells[c.cells_above[0]];
      EXPECT_EQ(floor.floor_z, 2.8);
      EXPECT_EQ(floor.top_z, 5.6);
      EXPECT_NE(std::find(floor.cells_below.begin(), floor.cells_below.end(), k),
                floor.cells_below.end());
    } else {
      EXPECT_EQ(c.cells_below.size(), 4u);
      EXPECT_FALSE(c.bottom_outside);
      EXPECT_TRUE(c.top_outside);
    }
  }
  EXPECT_EQ(rooms, 4u);
}

}  // namespace
}  // namespace roomcad
