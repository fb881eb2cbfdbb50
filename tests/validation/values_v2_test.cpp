// SPDX-License-Identifier: GPL-3.0-or-later
// invalid_value and unknown_reference for the version-2 objects and fields.
#include <gtest/gtest.h>

#include "plan_cases.h"

namespace roomcad {
namespace {

using namespace roomcad::testing;

Plan storey() {
  Plan p = plan_with({make_wall("a", {0, 0}, {4, 0})});
  p.levels.push_back(Level{.id = "up", .elevation = 3.0, .height = 2.6});
  p.walls[0].level = "up";
  p.slabs.push_back(
      Slab{.id = "floor", .level = "up", .outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}}});
  return p;
}

TEST(ValuesVersion2, EachBadNewValueIsOneInvalidValue) {
  const std::vector<std::pair<const char*, std::function<void(Plan&)>>> mistakes = {
      {"zero arc extent", [](Plan& p) { p.walls[0].arc_extent = 0.0; }},
      {"full turn", [](Plan& p) { p.walls[0].arc_extent = -360.0; }},
      {"negative height at end", [](Plan& p) { p.walls[0].height_at_end = -1.0; }},
      {"two-corner shape",
       [](Plan& p) {
         p.openings.push_back(make_opening("o", OpeningType::window, "a", 1, 1, 1, 1));
         p.openings[0].shape = {{0, 0}, {1, 1}};
       }},
      {"slab of two corners", [](Plan& p) { p.slabs[0].outline.resize(2); }},
      {"hole with a NaN",
       [](Plan& p) {
         p.slabs[0].holes = {{{1, 1}, {2, 1}, {2, NAN}}};
       }},
      {"zero slab thickness", [](Plan& p) { p.slabs[0].thickness = 0; }},
      {"zero level height", [](Plan& p) { p.levels[0].height = 0; }},
      {"NaN elevation", [](Plan& p) { p.levels[0].elevation = NAN; }},
      {"zero chord tolerance", [](Plan& p) { p.site.chord_tolerance = 0.0; }},
  };
  for (const auto& [name, apply] : mistakes) {
    SCOPED_TRACE(name);
    Plan p = storey();
    apply(p);
    const Report r = validate(p, no_rooms());
    EXPECT_EQ(error_codes(r), Codes{Code::invalid_value});
  }
  EXPECT_TRUE(validate(storey(), no_rooms()).ok());
}

TEST(ValuesVersion2, ALevelNamingNoLevelIsAnUnknownReference) {
  Plan p = storey();
  p.walls[0].level = "attic";
  p.slabs[0].level = "roof";
  const Report r = validate(p, no_rooms());
  EXPECT_EQ(error_codes(r), (Codes{Code::unknown_reference, Code::unknown_reference}));
  EXPECT_EQ(r.items[0].objects, Ids{"a"});
  EXPECT_EQ(r.items[1].objects, Ids{"floor"});
}

TEST(ValuesVersion2, IdsAreUniqueAcrossLevelsAndSlabsToo) {
  Plan p = storey();
  p.slabs[0].id = "up";
  EXPECT_EQ(error_codes(validate(p, no_rooms())), Codes{Code::duplicate_id});
}

}  // namespace
}  // namespace roomcad
