// SPDX-License-Identifier: GPL-3.0-or-later
// The window's edit session: grid-step moves, turns, deletes (with confirmation), undo,
// validated atomic saves and reloads, all on a real plan file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "io/plan_json.h"
#include "support/run_command.h"
#include "support/session_reloaded.h"
#include "view/view_session.h"

namespace roomcad {
namespace {

/// Two walls meeting at a corner on a 0.5 m grid, a door in the first, a light.
Plan corner_plan() {
  Plan p;
  p.site.cell_size = 0.5;
  Wall& a = p.walls.emplace_back();
  a.id = "a", a.from = {1, 1}, a.to = {5, 1};
  Wall& b = p.walls.emplace_back();
  b.id = "b", b.from = {5, 1}, b.to = {5, 4};
  Opening& d = p.openings.emplace_back();
  d.id = "d", d.wall = "a", d.offset = 1.0;
  p.lights.emplace_back().id = "sun";
  return p;
}

struct SessionFile {
  test::TempDir dir;
  std::filesystem::path path = dir / "plan.json";
  explicit SessionFile(const Plan& plan) {
    EXPECT_TRUE(test::write_bytes(path, write_plan_text(plan)));
  }
  ViewSession open() const {
    Result<ViewSession> s = ViewSession::open(path);
    EXPECT_TRUE(s.ok()) << s.error();
    return std::move(s).value();
  }
  Plan on_disk() const { return read_plan_file(path).value(); }
};

TEST(ViewSession, AnActionNotDoneSaysWhyWithItsCode) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  EXPECT_EQ(s.move_selection(1, 0).code(), Code::usage_error);   // nothing selected
  EXPECT_EQ(s.undo().code(), Code::usage_error);                 // nothing to undo
  EXPECT_EQ(s.keep_window_version().code(), Code::usage_error);  // no conflict
  s.select("a");
  const Status held = s.delete_selection();  // it holds door d: asks first
  EXPECT_EQ(held.code(), Code::edit_refused);
  EXPECT_EQ(held.message(), s.message());
  s.select("sun");
  EXPECT_EQ(s.move_selection(1, 0).code(), Code::precondition);  // a light has no position
  s.select("b");
  ASSERT_TRUE(s.move_selection(-20, 0));  // past wall a's far end: overlaps or leaves the site
  const Status refused = s.save();
  EXPECT_EQ(refused.code(), Code::edit_refused) << refused.message();
  EXPECT_EQ(file.on_disk(), corner_plan());  // nothing written
}

TEST(ViewSession, MovesTheSelectionByWholeCellsAndUndoes) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  EXPECT_FALSE(s.move_selection(1, 0));  // nothing selected
  s.select("b");
  ASSERT_TRUE(s.move_selection(1, -2)) << s.message();
  EXPECT_EQ(s.plan().walls[1].from, (Point2{5.5, 0.0}));
  EXPECT_EQ(s.plan().walls[1].to, (Point2{5.5, 3.0}));
  EXPECT_TRUE(s.is_modified());
  s.select("d");
  ASSERT_TRUE(s.move_selection(-1, 0));
  EXPECT_EQ(s.plan().openings[0].offset, 0.5);  // a door slides along its wall
  ASSERT_TRUE(s.undo());
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.plan(), corner_plan());
  EXPECT_FALSE(s.undo());
  EXPECT_EQ(s.message(), "nothing to undo");
}

TEST(ViewSession, RefusedEditsSayWhyAndChangeNothing) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  s.select("sun");
  const std::uint64_t revision = s.revision();
  EXPECT_FALSE(s.move_selection(1, 0));  // a directional light has no position
  EXPECT_NE(s.message().find("not done"), std::string::npos) << s.message();
  EXPECT_EQ(s.revision(), revision);
  EXPECT_EQ(s.undo_depth(), 0u);
  s.select("no-such-id");
  EXPECT_FALSE(s.selected());
}

TEST(ViewSession, TurnsTheSelectionAQuarter) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  s.select("b");
  ASSERT_TRUE(s.rotate_selection(90.0));
  EXPECT_EQ(s.plan().walls[1].from, (Point2{6.5, 2.5}));
  EXPECT_EQ(s.plan().walls[1].to, (Point2{3.5, 2.5}));
}

TEST(ViewSession, DeletingAWallWithOpeningsNeedsConfirmation) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  s.select("a");
  EXPECT_FALSE(s.delete_selection());
  EXPECT_NE(s.message().find("press Delete again"), std::string::npos) << s.message();
  EXPECT_EQ(s.plan().walls.size(), 2u);
  ASSERT_TRUE(s.delete_selection());
  EXPECT_EQ(s.plan().walls.size(), 1u);
  EXPECT_TRUE(s.plan().openings.empty());
  EXPECT_FALSE(s.selected());
  s.select("b");
  ASSERT_TRUE(s.delete_selection());  // no openings: at once
  EXPECT_TRUE(s.plan().walls.empty());
}

TEST(ViewSession, SavesOnlyAValidPlanAndMarksErrors) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  const std::string before = test::read_bytes(file.path);
  s.select("b");
  ASSERT_TRUE(
      s.move_selection(-20, 0));  // onto wall a's far end and past: overlaps or leaves the site
  ASSERT_FALSE(s.report().ok());
  EXPECT_NE(s.message().find("introduces"), std::string::npos) << s.message();
  EXPECT_FALSE(s.error_objects().empty());
  EXPECT_FALSE(s.save());
  EXPECT_NE(s.message().find("not saved"), std::string::npos);
  EXPECT_EQ(test::read_bytes(file.path), before);
  ASSERT_TRUE(s.undo());
  ASSERT_TRUE(s.move_selection(1, 0));
  ASSERT_TRUE(s.save()) << s.message();
  EXPECT_EQ(file.on_disk(), s.plan());
  EXPECT_FALSE(s.is_modified());
  EXPECT_FALSE(test::reloaded(s));  // its own write is not a change on disk
}

TEST(ViewSession, ReloadsWhenTheFileChanges) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  EXPECT_FALSE(test::reloaded(s));
  Plan changed = corner_plan();
  changed.walls[0].height = 3.0;
  const auto later = std::filesystem::last_write_time(file.path) + std::chrono::seconds(2);
  ASSERT_TRUE(test::write_bytes(file.path, write_plan_text(changed)));
  std::filesystem::last_write_time(file.path, later);
  ASSERT_TRUE(test::reloaded(s));
  EXPECT_EQ(s.plan(), changed);
  ASSERT_TRUE(test::write_bytes(file.path, "{ not json"));
  std::filesystem::last_write_time(file.path, later + std::chrono::seconds(2));
  EXPECT_FALSE(test::reloaded(s));
  EXPECT_EQ(s.plan(), changed);
  EXPECT_NE(s.message().find("not a valid plan"), std::string::npos) << s.message();
  ASSERT_TRUE(s.undo());  // back to what was shown before the reload
  EXPECT_EQ(s.plan(), corner_plan());
}

TEST(ViewSession, SelectNextCyclesThroughEveryObject) {
  SessionFile file(corner_plan());
  ViewSession s = file.open();
  std::vector<std::string> seen;
  for (int i = 0; i < 5; ++i) {
    s.select_next();
    seen.push_back(s.selected().value_or(""));
  }
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b", "d", "sun", "a"}));
  EXPECT_EQ(s.selection_properties().front(), "wall a");
}

TEST(ViewSession, OpenNamesTheFileThatIsNotAPlan) {
  test::TempDir dir;
  ASSERT_TRUE(test::write_bytes(dir / "bad.json", "{\"format\": 3}"));
  const Result<ViewSession> s = ViewSession::open(dir / "bad.json");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("bad.json"), std::string::npos) << s.error();
}

}  // namespace
}  // namespace roomcad
