// SPDX-License-Identifier: GPL-3.0-or-later
// The edit commands (add, rm, move, rotate, scale, set) run as a user runs them: the roomcad
// binary (ROOMCAD_EXE) on temporary canonical copies of tests/cli/data/edit_room.json and of
// examples/*.json.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "io/plan_json.h"
#include "io/plan_lock.h"
#include "support/plan_reading.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;
using test::read_bytes;

/// Splits on spaces (the arguments of these tests hold none).
std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

class EditCommands : public ::testing::Test {
 protected:
  /// Writes the canonical text of a plan file into the temporary folder; @return its path.
  fs::path canonical_copy(const fs::path& source) {
    const test::PlanReading read = test::read_plan_at(source);
    EXPECT_TRUE(read.plan.has_value()) << source;
    const fs::path copy = dir_ / source.filename().string();
    EXPECT_TRUE(test::write_bytes(copy, write_plan_text(*read.plan)));
    return copy;
  }
  fs::path room() { return canonical_copy(test::source_dir() / "tests/cli/data/edit_room.json"); }

  /// Runs `roomcad <verb> <plan> <rest...>`.
  CommandResult edit(const std::string& verb, const fs::path& plan, const std::string& rest) {
    std::vector<std::string> args{verb, plan.string()};
    for (std::string& w : words(rest)) args.push_back(std::move(w));
    return test::run_roomcad(args);
  }
  Plan load(const fs::path& path) { return read_plan_file(path).value(); }

  /// Expects the edit to end with `status`, saying `says` on stderr, leaving the file byte for
  /// byte as it was.
  void expect_untouched(int status, const std::string& verb, const fs::path& plan,
                        const std::string& rest, const std::string& says) {
    const std::string before = read_bytes(plan);
    const CommandResult r = edit(verb, plan, rest);
    EXPECT_EQ(r.status, status) << verb << " " << rest << "\n" << r.out << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << "stderr lacks '" << says << "':\n" << r.err;
    EXPECT_EQ(read_bytes(plan), before) << verb << " " << rest;
  }

  test::TempDir dir_;
};

TEST_F(EditCommands, AddsEachKindWithGeneratedIds) {
  const fs::path plan = room();
  EXPECT_EQ(edit("add", plan, "wall --from 3,3 --to 5.5,3 --thickness 0.2 --color #112233").status,
            0);
  EXPECT_EQ(edit("add", plan, "door --wall west --offset 2 --hinge right").status, 0);
  EXPECT_EQ(edit("add", plan, "window --id w9 --wall east --offset 2 --width 1.2").status, 0);
  EXPECT_EQ(edit("add", plan, "light --direction 0.3,0.2,-1 --ambient 0.4").status, 0);
  const CommandResult r =
      edit("add", plan, "camera --eye 6,4,20 --target 6,4,0 --up 0,1,0 --projection orthographic");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "+ camera-1\n");
  const Plan p = load(plan);
  ASSERT_EQ(p.walls.size(), 5u);
  EXPECT_EQ(p.walls[4].id, "wall-1");
  EXPECT_EQ(p.walls[4].to, (Point2{5.5, 3}));
  EXPECT_EQ(p.walls[4].color, (Color{0x11, 0x22, 0x33}));
  EXPECT_EQ(p.openings[2].id, "door-1");
  EXPECT_EQ(p.openings[2].hinge, Hinge::right);
  EXPECT_EQ(p.openings[3].id, "w9");
  EXPECT_EQ(p.openings[3].sill, 0.9);  // a window's default
  EXPECT_EQ(p.lights[1].id, "light-1");
  EXPECT_EQ(p.cameras[1].projection, Projection::orthographic);
}

TEST_F(EditCommands, AnAddThatIntroducesAnErrorIsRefusedUnlessForced) {
  const fs::path plan = room();
  expect_untouched(1, "add", plan, "wall --from 2,1.3 --to 4,1.3", "wall_overlap");
  expect_untouched(1, "add", plan, "door --wall south --offset 1.8", "opening_overlap");
  expect_untouched(1, "add", plan, "wall --from 3,3 --to 30,3", "out_of_bounds");
  const CommandResult forced = edit("add", plan, "wall --from 2,1.3 --to 4,1.3 --force");
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_NE(forced.err.find("wall_overlap"), std::string::npos);
  EXPECT_EQ(load(plan).walls.size(), 5u);
}

TEST_F(EditCommands, DryRunShowsTheChangeAndWritesNothing) {
  const fs::path plan = room();
  const std::string before = read_bytes(plan);
  const CommandResult r = edit("set", plan, "south color=#102030 --dry-run");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("~ south"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("- "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("#102030"), std::string::npos) << r.out;
  EXPECT_EQ(read_bytes(plan), before);
  EXPECT_EQ(edit("rotate", plan, "--all --deg 90 --dry-run").status, 0);
  EXPECT_EQ(read_bytes(plan), before);
}

TEST_F(EditCommands, RmRefusesAWallWithOpeningsUnlessCascade) {
  const fs::path plan = room();
  expect_untouched(1, "rm", plan, "south", "entry");
  EXPECT_EQ(edit("rm", plan, "win1").status, 0);
  EXPECT_EQ(edit("rm", plan, "view").status, 0);
  const CommandResult r = edit("rm", plan, "south --cascade");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "- south\n- entry\n");
  const Plan p = load(plan);
  EXPECT_EQ(p.walls.size(), 3u);
  EXPECT_TRUE(p.openings.empty());
  EXPECT_TRUE(p.cameras.empty());
}

TEST_F(EditCommands, MoveThenMoveBackRestoresTheFile) {
  const fs::path plan = room();
  const std::string before = read_bytes(plan);
  EXPECT_EQ(edit("move", plan, "--all --by 0.1,-0.35").status, 0);
  EXPECT_NE(read_bytes(plan), before);
  EXPECT_EQ(edit("move", plan, "--all --by -0.1,0.35").status, 0);
  EXPECT_EQ(read_bytes(plan), before);
  EXPECT_EQ(edit("move", plan, "entry --by 0.3").status, 0);  // along its wall
  EXPECT_EQ(load(plan).openings[0].offset, 1.85);
  EXPECT_EQ(edit("move", plan, "entry --by -0.3").status, 0);
  EXPECT_EQ(edit("move", plan, "view --by 1.7,-0.2").status, 0);
  EXPECT_EQ(edit("move", plan, "view --by -1.7,0.2").status, 0);
  EXPECT_EQ(read_bytes(plan), before);
}

TEST_F(EditCommands, MovingAWallOutOfTheSiteIsRefused) {
  const fs::path plan = room();
  expect_untouched(1, "move", plan, "south --by 0,-2", "out_of_bounds");
  // Off its corners by 0.1 the wall still meets both side walls (its ends lie on their centre
  // lines: T joins), so that move is valid.
  EXPECT_EQ(edit("move", plan, "south --by 0,0.1").status, 0);
}

TEST_F(EditCommands, RotateAndScaleObjects) {
  const fs::path plan = room();
  EXPECT_EQ(edit("rotate", plan, "sun --deg 90").status, 0);
  EXPECT_EQ(load(plan).lights[0].direction, (Vec3{-0.5, -0.4, -1}));
  EXPECT_EQ(edit("rotate", plan, "view --deg 30").status, 0);
  EXPECT_EQ(load(plan).cameras[0].target, (Vec3{5.9, 3.85, 1}));  // turned about its target
  expect_untouched(2, "rotate", plan, "entry --deg 90", "opening");
  expect_untouched(1, "scale", plan, "south --factor 1.5 --about 1.1,1.3", "refused");
  EXPECT_EQ(edit("scale", plan, "--all --factor 0.5 --about 0,0").status, 0);
  const Plan p = load(plan);
  EXPECT_EQ(p.walls[0].to, (Point2{5.35, 0.65}));
  EXPECT_EQ(p.site.cell_size, 0.5);
  EXPECT_EQ(p.walls[0].thickness, 0.25);
}

/// The plans the round trips run on: the edit fixture and every example.
std::vector<fs::path> round_trip_plans() {
  std::vector<fs::path> plans{test::source_dir() / "tests/cli/data/edit_room.json"};
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "examples", ec))
    if (entry.path().extension() == ".json") plans.push_back(entry.path());
  return plans;
}

constexpr const char* kNotUndoable = "would not restore";

/// After a round trip that warned it could not be exact: the walls came back within 1e-12 m.
void expect_walls_near(const Plan& a, const Plan& b, const fs::path& source) {
  ASSERT_EQ(a.walls.size(), b.walls.size()) << source;
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    EXPECT_NEAR(a.walls[i].from.x, b.walls[i].from.x, 1e-12) << source << " " << a.walls[i].id;
    EXPECT_NEAR(a.walls[i].from.y, b.walls[i].from.y, 1e-12) << source << " " << a.walls[i].id;
    EXPECT_NEAR(a.walls[i].to.x, b.walls[i].to.x, 1e-12) << source << " " << a.walls[i].id;
    EXPECT_NEAR(a.walls[i].to.y, b.walls[i].to.y, 1e-12) << source << " " << a.walls[i].id;
  }
}

/// The guarantee: byte for byte unless some step warned (numbers beyond 15 digits), and the
/// fixture, whose numbers are short decimals, never warns.
void expect_restored(const fs::path& plan, const std::string& before, int warnings,
                     const fs::path& source) {
  if (source.filename() == "edit_room.json") {
    EXPECT_EQ(warnings, 0);
  }
  if (warnings == 0) {
    EXPECT_EQ(read_bytes(plan), before) << source;
    return;
  }
  const test::PlanReading original = test::read_plan(before, "before");
  expect_walls_near(read_plan_file(plan).value(), original.plan.value(), source);
}

TEST_F(EditCommands, FourQuarterTurnsOfTheWholePlanAreIdentity) {
  for (const fs::path& source : round_trip_plans()) {
    const fs::path plan = canonical_copy(source);
    const std::string before = read_bytes(plan);
    int warnings = 0;
    for (int turn = 0; turn < 4; ++turn) {
      const CommandResult r = edit("rotate", plan, "--all --deg 90 --force");
      EXPECT_EQ(r.status, 0) << source << "\n" << r.err;
      warnings += r.err.find(kNotUndoable) != std::string::npos;
      if (turn == 0) {
        EXPECT_NE(read_bytes(plan), before) << source;
      }
    }
    expect_restored(plan, before, warnings, source);
  }
}

TEST_F(EditCommands, MoveThenMoveBackIsIdentityOnEveryPlan) {
  for (const fs::path& source : round_trip_plans()) {
    const fs::path plan = canonical_copy(source);
    const std::string before = read_bytes(plan);
    const CommandResult there = edit("move", plan, "--all --by 0.7,-1.3 --force");
    EXPECT_EQ(there.status, 0) << source;
    EXPECT_EQ(edit("move", plan, "--all --by -0.7,1.3 --force").status, 0) << source;
    expect_restored(plan, before, there.err.find(kNotUndoable) != std::string::npos, source);
  }
}

TEST_F(EditCommands, AMoveThatCannotBeUndoneExactlySaysSo) {
  const fs::path plan = room();
  // A corner computed at 30 degrees: 17 significant digits, more than a double keeps after a
  // move by 1.3.
  EXPECT_EQ(edit("set", plan, "view target=5.9,11.830127018922195,1").status, 0);
  const CommandResult r = edit("move", plan, "view --by 0,-1.3");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("would not restore view bit for bit"), std::string::npos) << r.err;
  const CommandResult quiet = edit("move", plan, "south --by 0,0.1");
  EXPECT_EQ(quiet.err.find(kNotUndoable), std::string::npos) << quiet.err;
}

TEST_F(EditCommands, ScaleUpThenDownIsIdentityForShortDecimals) {
  const fs::path plan = room();
  const std::string before = read_bytes(plan);
  EXPECT_EQ(edit("scale", plan, "--all --factor 2").status, 0);
  EXPECT_NE(read_bytes(plan), before);
  EXPECT_EQ(edit("scale", plan, "--all --factor 0.5").status, 0);
  EXPECT_EQ(read_bytes(plan), before);
}

TEST_F(EditCommands, SetFieldsTypeCheckedAndValidated) {
  const fs::path plan = room();
  const CommandResult r = edit("set", plan, "south color=#102030 height=3");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(load(plan).walls[0].height, 3.0);
  expect_untouched(2, "set", plan, "south colour=#ffffff", "did you mean 'color'?");
  expect_untouched(2, "set", plan, "south thickness=thick", "wants metres, got 'thick'");
  expect_untouched(1, "set", plan, "south thickness=-1", "invalid_value");
  EXPECT_EQ(edit("set", plan, "south id=front").status, 0);
  EXPECT_EQ(load(plan).openings[0].wall, "front");
  EXPECT_EQ(edit("set", plan, "site cells=14,9").status, 0);
  const std::string before = read_bytes(plan);
  EXPECT_EQ(edit("set", plan, "front height=3").out,
            "nothing to change: '" + plan.string() + "' is left as it was\n");
  EXPECT_EQ(read_bytes(plan), before);
}

TEST_F(EditCommands, BadArgumentsExitTwoWithAClearMessage) {
  const fs::path plan = room();
  expect_untouched(2, "move", plan, "ghost --by 1,1", "no object has id 'ghost'");
  expect_untouched(2, "move", plan, "south --by left", "--by wants dx,dy in metres (or one number");
  expect_untouched(2, "move", plan, "--all --by 1", "--by wants dx,dy in metres, got '1'");
  expect_untouched(2, "move", plan, "--by 1,1", "or --all");
  expect_untouched(2, "move", plan, "south --all --by 1,1", "not both");
  expect_untouched(2, "move", plan, "sun --by 1,1", "no position");
  expect_untouched(2, "rotate", plan, "south --deg ninety", "--deg wants a finite number");
  expect_untouched(2, "scale", plan, "south --factor 0", "positive");
  expect_untouched(2, "add", plan, "wall --from 1,1", "needs --to");
  expect_untouched(2, "add", plan, "door --wall south --offset 1 --from 1,1",
                   "--from does not apply to a door");
  expect_untouched(2, "add", plan, "door --wall nowhere --offset 1", "'nowhere'");
  expect_untouched(2, "add", plan, "wall --id entry --from 3,3 --to 4,3", "already used");
  expect_untouched(2, "set", plan, "south thickness", "not key=value");
  const CommandResult missing = edit("move", dir_ / "none.json", "south --by 1,1");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(test::failure_code(missing), Code::io_error);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir_ / "none.json"));
}

TEST_F(EditCommands, EachCommandHasHelp) {
  for (const std::string verb : {"add", "rm", "move", "rotate", "scale", "set"}) {
    const CommandResult r = test::run_roomcad({verb, "--help"});
    EXPECT_EQ(r.status, 0) << verb;
    EXPECT_NE(r.out.find("Examples:"), std::string::npos) << verb << "\n" << r.out;
    EXPECT_NE(r.out.find("--dry-run"), std::string::npos) << verb;
    EXPECT_NE(r.out.find("--wait SECONDS"), std::string::npos) << verb;
  }
}

TEST_F(EditCommands, EveryEditWaitsForThePlansLockThenGivesUpNamingTheHolder) {
  const fs::path plan = room();
  const std::string before = read_bytes(plan);
  const Result<PlanLock> held =
      PlanLock::acquire(plan, std::chrono::milliseconds(0), "roomcad view");
  ASSERT_TRUE(held.ok()) << held.error();
  const std::vector<std::pair<std::string, std::string>> edits{
      {"add", "light --direction 0,0,-1"}, {"rm", "win1"},
      {"move", "south --by 0,0.1"},        {"rotate", "win1 --deg 0"},
      {"scale", "--all --factor 2"},       {"set", "south height=2.5"}};
  for (const auto& [verb, rest] : edits) {
    const CommandResult r = edit(verb, plan, rest + " --wait 0.2");
    EXPECT_EQ(r.status, 2) << verb;
    EXPECT_EQ(test::failure_code(r), Code::lock_timeout) << verb << ": " << r.err;
    const std::string says = fmt::format(
        "roomcad {}: error[lock_timeout]: {} is locked by another editor (pid {}, roomcad view), "
        "which did not "
        "release it within 0.2 s; --wait SECONDS waits longer",
        verb, plan.string(), ::getpid());
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  }
  const CommandResult formatted = test::run_roomcad({"fmt", plan.string(), "--wait", "0"});
  EXPECT_EQ(formatted.status, 2);
  EXPECT_EQ(test::failure_code(formatted), Code::lock_timeout) << formatted.err;
  EXPECT_NE(formatted.err.find("locked by another editor"), std::string::npos) << formatted.err;
  EXPECT_EQ(read_bytes(plan), before);
  // Reading needs no lock: a dry run and fmt --check go on.
  EXPECT_EQ(edit("move", plan, "south --by 0,0.1 --dry-run --wait 0").status, 0);
  EXPECT_EQ(test::run_roomcad({"fmt", "--check", plan.string(), "--wait", "0"}).status, 0);
}

}  // namespace
}  // namespace roomcad
