// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan/nearest_name.h"

#include <gtest/gtest.h>

#include <array>

namespace roomcad {
namespace {

TEST(NearestName, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("height", "height"), 0u);
  EXPECT_EQ(edit_distance("heigth", "height"), 2u);  // a swap is two substitutions
  EXPECT_EQ(edit_distance("colour", "color"), 1u);
  EXPECT_EQ(edit_distance("", "base"), 4u);
}

TEST(NearestName, SuggestsOnlyCloseNames) {
  const std::array<std::string_view, 3> names{"thickness", "height", "color"};
  EXPECT_EQ(nearest_name("colour", names), std::optional<std::string_view>("color"));
  EXPECT_EQ(nearest_name("heigth", names), std::optional<std::string_view>("height"));
  EXPECT_EQ(nearest_name("material", names), std::nullopt);
  EXPECT_EQ(nearest_name("colour", names, 0), std::nullopt);
}

}  // namespace
}  // namespace roomcad
