// SPDX-License-Identifier: GPL-3.0-or-later
// --keys scripts: every form parses to the events a person would cause; bad items are named.
#include <gtest/gtest.h>

#include "view/input.h"
#include "view/key_bindings.h"

namespace roomcad {
namespace {

TEST(KeyScript, ParsesKeysModifiersAndPointerInputs) {
  const auto events =
      parse_key_script("1,ctrl+s,shift+x,ctrl+shift+z,click:640:360,drag:-40:5,pan:3:4,wheel:-2");
  ASSERT_TRUE(events.ok()) << events.error();
  const std::vector<InputEvent>& e = events.value();
  ASSERT_EQ(e.size(), 8u);
  EXPECT_EQ(e[0].key, "1");
  EXPECT_TRUE(e[1].ctrl && !e[1].shift && e[1].key == "s");
  EXPECT_TRUE(!e[2].ctrl && e[2].shift && e[2].key == "x");
  EXPECT_TRUE(e[3].ctrl && e[3].shift && e[3].key == "z");
  EXPECT_EQ(e[4].type, InputEvent::Type::click);
  EXPECT_EQ(e[4].x, 640);
  EXPECT_EQ(e[4].y, 360);
  EXPECT_EQ(e[5].type, InputEvent::Type::drag);
  EXPECT_EQ(e[5].x, -40);
  EXPECT_FALSE(e[5].right_button);
  EXPECT_TRUE(e[6].right_button);
  EXPECT_EQ(e[7].type, InputEvent::Type::wheel);
  EXPECT_EQ(e[7].x, -2);
  EXPECT_TRUE(parse_key_script("").value().empty());
  const auto wait = parse_key_script("ctrl+s,wait:change,ctrl+k");
  ASSERT_TRUE(wait.ok()) << wait.error();
  EXPECT_EQ(wait.value()[1].type, InputEvent::Type::wait_change);
}

TEST(KeyScript, NamesTheBadItem) {
  for (const char* bad : {"1,,2", "ctrl+", "f13", "click:1", "click:a:2", "click:-1:4", "wheel:1:2",
                          "drag:1:2:3", "LEFT", "ctrl+ctrl", "wait:5", "wait:"}) {
    const auto events = parse_key_script(bad);
    ASSERT_FALSE(events.ok()) << bad;
    EXPECT_EQ(events.code(), Code::usage_error) << bad;
    EXPECT_NE(events.message().find("--keys: input"), std::string::npos) << events.error();
  }
  EXPECT_NE(parse_key_script("a,f13").message().find("input 2 'f13'"), std::string::npos);
  EXPECT_NE(parse_key_script("wait:5").message().find("expected wait:change"), std::string::npos);
}

TEST(KeyBindings, EveryBindingIsAKeyAndUnique) {
  const auto bindings = key_bindings();
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    EXPECT_TRUE(is_key_name(bindings[i].key)) << bindings[i].key;
    for (std::size_t j = i + 1; j < bindings.size(); ++j)
      EXPECT_FALSE(bindings[i].key == bindings[j].key && bindings[i].ctrl == bindings[j].ctrl &&
                   bindings[i].shift == bindings[j].shift)
          << bindings[i].key;
  }
  const std::vector<InputEvent> keys = parse_key_script("ctrl+s,s,k,ctrl+r,ctrl+k").value();
  EXPECT_EQ(action_for(keys[0]), Action::save);
  EXPECT_EQ(action_for(keys[1]), Action::orbit_down);
  EXPECT_FALSE(action_for(keys[2]));
  EXPECT_EQ(action_for(keys[3]), Action::reload_file);
  EXPECT_EQ(action_for(keys[4]), Action::keep_window_version);
  for (const char* listed : {"ctrl+s", "ctrl+r", "ctrl+k"})
    EXPECT_NE(key_help().find(listed), std::string::npos) << listed;
}

}  // namespace
}  // namespace roomcad
