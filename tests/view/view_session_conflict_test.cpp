// SPDX-License-Identifier: GPL-3.0-or-later
// The window's session and other editors of its file: a change on disk is reloaded when the
// window has no unsaved edits; with unsaved edits (or at a save over a changed file) it is a
// conflict, where nothing is saved or dropped until the person chooses: reload the file, or
// keep the window's version. Saves hold the plan's lock.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "io/plan_json.h"
#include "io/plan_lock.h"
#include "support/run_command.h"
#include "support/session_reloaded.h"
#include "view/view_session.h"

namespace roomcad {
namespace {

using std::chrono::milliseconds;

/// Two walls, a and b, on a 0.5 m grid.
Plan two_walls() {
  Plan p;
  p.site.cell_size = 0.5;
  for (const double y : {1.0, 3.0}) {
    Wall& w = p.walls.emplace_back();
    w.id = std::string(1, static_cast<char>('a' + p.walls.size() - 1));
    w.from = {1, y}, w.to = {5, y};
  }
  return p;
}

/// The plan another editor saves: wall a taller.
Plan their_plan() {
  Plan p = two_walls();
  p.walls[0].height = 3.0;
  return p;
}

class ViewSessionConflict : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(write_plan_file(two_walls(), path_).ok()); }
  ViewSession open(milliseconds lock_wait = milliseconds(2000)) {
    Result<ViewSession> s = ViewSession::open(path_, lock_wait);
    EXPECT_TRUE(s.ok()) << s.error();
    return std::move(s).value();
  }
  /// The window's edit: wall b one cell east.
  static void edit(ViewSession& s) {
    s.select("b");
    ASSERT_TRUE(s.move_selection(1, 0));
    ASSERT_TRUE(s.is_modified());
  }
  static Plan our_plan() {
    Plan p = two_walls();
    p.walls[1].from.x += 0.5, p.walls[1].to.x += 0.5;
    return p;
  }
  /// Another editor saves `plan` (atomically, as roomcad does).
  void they_save(const Plan& plan) { ASSERT_TRUE(write_plan_file(plan, path_).ok()); }
  Plan on_disk() const { return read_plan_file(path_).value(); }

  test::TempDir dir_;
  std::filesystem::path path_ = dir_ / "plan.json";
};

TEST_F(ViewSessionConflict, AChangeWithoutUnsavedEditsIsReloaded) {
  ViewSession s = open();
  they_save(their_plan());
  EXPECT_TRUE(test::reloaded(s));
  EXPECT_EQ(s.plan(), their_plan());
  EXPECT_FALSE(s.in_conflict());
  EXPECT_FALSE(s.is_modified());
  EXPECT_EQ(s.disk_changes(), 1u);
}

TEST_F(ViewSessionConflict, RewritingTheSameBytesIsNoChange) {
  ViewSession s = open();
  edit(s);
  they_save(two_walls());  // a new file (inode, time), the same bytes
  EXPECT_FALSE(test::reloaded(s));
  EXPECT_FALSE(s.in_conflict());
  EXPECT_EQ(s.disk_changes(), 0u);
  EXPECT_EQ(s.plan(), our_plan());
}

TEST_F(ViewSessionConflict, UndoingBackToTheFileLeavesNoUnsavedEdits) {
  ViewSession s = open();
  edit(s);
  ASSERT_TRUE(s.undo());
  EXPECT_FALSE(s.is_modified());
  they_save(their_plan());
  EXPECT_TRUE(test::reloaded(s));  // nothing of the window's to lose: reloaded
  EXPECT_FALSE(s.in_conflict());
}

TEST_F(ViewSessionConflict, AChangeWithUnsavedEditsIsAConflictThatKeepsBothSides) {
  ViewSession s = open();
  edit(s);
  they_save(their_plan());
  EXPECT_FALSE(test::reloaded(s));
  ASSERT_TRUE(s.in_conflict());
  EXPECT_EQ(s.disk_changes(), 1u);
  EXPECT_NE(s.message().find("changed on disk and the window has unsaved edits"),
            std::string::npos);
  EXPECT_NE(s.message().find("Ctrl+R"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("Ctrl+K"), std::string::npos) << s.message();
  EXPECT_EQ(s.plan(), our_plan());  // the window's edits are kept
  EXPECT_FALSE(s.save());           // and not saved over theirs
  EXPECT_TRUE(s.in_conflict());
  EXPECT_EQ(on_disk(), their_plan());
  EXPECT_FALSE(test::reloaded(s));  // nothing new
  EXPECT_EQ(s.disk_changes(), 1u);
}

TEST_F(ViewSessionConflict, ReloadTakesTheFileAndUndoBringsTheEditsBack) {
  ViewSession s = open();
  edit(s);
  they_save(their_plan());
  test::reloaded(s);
  ASSERT_TRUE(s.reload_file());
  EXPECT_EQ(s.plan(), their_plan());
  EXPECT_FALSE(s.in_conflict());
  EXPECT_FALSE(s.is_modified());
  EXPECT_NE(s.message().find("edits dropped"), std::string::npos) << s.message();
  EXPECT_EQ(on_disk(), their_plan());
  ASSERT_TRUE(s.undo());
  EXPECT_EQ(s.plan(), our_plan());
  EXPECT_TRUE(s.is_modified());
}

TEST_F(ViewSessionConflict, KeepSavesTheWindowsVersionOverTheFile) {
  ViewSession s = open();
  edit(s);
  they_save(their_plan());
  test::reloaded(s);
  ASSERT_TRUE(s.keep_window_version()) << s.message();
  EXPECT_EQ(on_disk(), our_plan());
  EXPECT_FALSE(s.in_conflict());
  EXPECT_FALSE(s.is_modified());
  EXPECT_FALSE(test::reloaded(s));        // its own save is no change
  EXPECT_FALSE(s.keep_window_version());  // no conflict: nothing to keep
  EXPECT_NE(s.message().find("nothing to keep"), std::string::npos) << s.message();
}

TEST_F(ViewSessionConflict, KeepIsRefusedWhenTheFileChangedAgain) {
  ViewSession s = open();
  edit(s);
  they_save(their_plan());
  test::reloaded(s);
  Plan again = their_plan();
  again.walls[0].thickness = 0.3;
  they_save(again);  // not yet seen by the window: its prompt showed the first change
  EXPECT_FALSE(s.keep_window_version());
  EXPECT_TRUE(s.in_conflict());
  EXPECT_NE(s.message().find("changed on disk again"), std::string::npos) << s.message();
  EXPECT_EQ(on_disk(), again);
  ASSERT_TRUE(s.keep_window_version()) << s.message();  // chosen again, for what is there now
  EXPECT_EQ(on_disk(), our_plan());
}

TEST_F(ViewSessionConflict, SavingOverAChangedFileGoesThroughThePrompt) {
  ViewSession s = open();
  edit(s);
  they_save(their_plan());  // the window has not polled: the save finds it
  EXPECT_FALSE(s.save());
  EXPECT_TRUE(s.in_conflict());
  EXPECT_NE(s.message().find("not saved"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("Ctrl+K"), std::string::npos) << s.message();
  EXPECT_EQ(on_disk(), their_plan());
  EXPECT_EQ(s.plan(), our_plan());
}

TEST_F(ViewSessionConflict, TheConflictEndsWhenTheFileComesBack) {
  ViewSession s = open();
  edit(s);
  const std::string original = test::read_bytes(path_);
  they_save(their_plan());
  test::reloaded(s);
  ASSERT_TRUE(s.in_conflict());
  ASSERT_TRUE(test::write_bytes(path_, original));
  EXPECT_FALSE(test::reloaded(s));
  EXPECT_FALSE(s.in_conflict());
  EXPECT_EQ(s.disk_changes(), 2u);
  ASSERT_TRUE(s.save()) << s.message();
  EXPECT_EQ(on_disk(), our_plan());
}

TEST_F(ViewSessionConflict, AFileThatIsNoLongerAPlanCanOnlyBeKeptOver) {
  ViewSession s = open();
  edit(s);
  ASSERT_TRUE(test::write_bytes(path_, "{ broken"));
  test::reloaded(s);
  ASSERT_TRUE(s.in_conflict());
  EXPECT_NE(s.message().find("not a valid plan"), std::string::npos) << s.message();
  EXPECT_FALSE(s.reload_file());
  EXPECT_NE(s.message().find("not reloaded"), std::string::npos) << s.message();
  EXPECT_EQ(s.plan(), our_plan());
  ASSERT_TRUE(s.keep_window_version()) << s.message();
  EXPECT_EQ(on_disk(), our_plan());
}

TEST_F(ViewSessionConflict, SaveWaitsForAnotherEditorsLockThenGivesUp) {
  ViewSession s = open(milliseconds(100));
  edit(s);
  const std::string before = test::read_bytes(path_);
  {
    const Result<PlanLock> other = PlanLock::acquire(path_, milliseconds(0), "roomcad add");
    ASSERT_TRUE(other.ok());
    EXPECT_FALSE(s.save());
    EXPECT_NE(s.message().find("not saved"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("locked by another editor"), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("roomcad add"), std::string::npos) << s.message();
    EXPECT_EQ(test::read_bytes(path_), before);
    EXPECT_TRUE(s.is_modified());
  }
  ASSERT_TRUE(s.save()) << s.message();
  EXPECT_EQ(on_disk(), our_plan());
}

}  // namespace
}  // namespace roomcad
