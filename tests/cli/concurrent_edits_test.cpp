// SPDX-License-Identifier: GPL-3.0-or-later
// No edit is lost (issue #17): processes editing one plan at once each see every other's edits
// (the plan's lock, io/plan_lock.h, makes each read-modify-write whole), and an editor killed
// at any point leaves a whole plan, old or new, and no lock that blocks the next one.
//
// Both tests run the roomcad binary (ROOMCAD_EXE) many times: they take seconds (CTest label
// slow).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/plan_json.h"
#include "support/run_command.h"
#include "validation/validate.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;

constexpr int kProcesses = 4;
constexpr int kEditsEach = 50;
constexpr int kSlots = 14;            ///< wall places along each process's row
constexpr const char* kWait = "600";  ///< --wait: no edit may give up, however loaded the machine

/// An empty plan with a site of 24 x 12 m: process k edits along the row y = 1 + 2.5 k.
Plan empty_site() {
  Plan plan;
  plan.site.cells = {24, 12};
  plan.site.cell_size = 1.0;
  return plan;
}

/// One process's edits, and what they leave: walls it owns (ids "p<k>-<n>"), each in a slot
/// of its row, moved up and down by half a metre, their height and colour set, some removed.
struct EditScript {
  std::vector<std::vector<std::string>> commands;  ///< roomcad arguments, after the plan
  std::map<std::string, Wall> walls;               ///< the process's walls at the end
  std::map<std::string, int> counts;               ///< edits of each verb
};

EditScript make_script(int process, int edits) {
  EditScript s;
  std::mt19937 random(1234 + process);
  std::map<std::string, int> slot_of;
  const double row = 1.0 + 2.5 * process;
  for (int i = 0, next_id = 0; i < edits; ++i) {
    const int op = s.walls.size() < 3 ? 0 : static_cast<int>(random() % 4);
    std::vector<int> free;
    for (int slot = 0; slot < kSlots; ++slot)
      if (std::none_of(slot_of.begin(), slot_of.end(),
                       [&](const auto& e) { return e.second == slot; }))
        free.push_back(slot);
    auto owned = s.walls.begin();
    std::advance(owned, random() % std::max<std::size_t>(s.walls.size(), 1));
    if (op == 0 && !free.empty()) {
      const std::string id = fmt::format("p{}-{}", process, next_id++);
      const double x = 0.5 + 1.5 * free[random() % free.size()];
      Wall w;
      w.id = id, w.from = {x, row}, w.to = {x + 1, row}, w.thickness = 0.1;
      s.commands.push_back({"add", "wall", "--id", id, "--from", fmt::format("{},{}", x, row),
                            "--to", fmt::format("{},{}", x + 1, row), "--thickness", "0.1"});
      slot_of[id] = static_cast<int>((x - 0.5) / 1.5);
      s.walls[id] = w;
      ++s.counts["add"];
    } else if (op == 1 || (op == 0 && free.empty())) {
      Wall& w = owned->second;
      const double dy = w.from.y == row ? 0.5 : -0.5;
      w.from.y += dy, w.to.y += dy;
      s.commands.push_back({"move", w.id, "--by", fmt::format("0,{}", dy)});
      ++s.counts["move"];
    } else if (op == 2) {
      Wall& w = owned->second;
      const std::string height = fmt::format("2.{}", i % 10);
      w.height = std::stod(height);
      w.color =
          Color{static_cast<std::uint8_t>(process * 60), static_cast<std::uint8_t>(i * 5), 0x80};
      s.commands.push_back(
          {"set", w.id, "height=" + height,
           fmt::format("color=#{:02x}{:02x}{:02x}", w.color.r, w.color.g, w.color.b)});
      ++s.counts["set"];
    } else {
      s.commands.push_back({"rm", owned->first});
      slot_of.erase(owned->first);
      s.walls.erase(owned);
      ++s.counts["rm"];
    }
  }
  return s;
}

/// Runs the script's commands one after the other in a child process; what failed goes to
/// `log`. @return the child's pid.
pid_t run_script_in_child(const fs::path& plan, const EditScript& script, const fs::path& log) {
  const pid_t child = ::fork();
  if (child != 0) return child;
  std::string failures;
  for (const auto& command : script.commands) {
    std::vector<std::string> args{command[0], plan.string()};
    args.insert(args.end(), command.begin() + 1, command.end());
    args.insert(args.end(), {"--wait", kWait});
    const test::CommandResult r = test::run_roomcad(args);
    if (r.status != 0)
      failures += fmt::format("{} -> {}: {}", fmt::join(args, " "), r.status, r.err);
  }
  test::write_bytes(log, failures);
  ::_exit(failures.empty() ? 0 : 1);
}

/// The plan's walls by id.
std::map<std::string, Wall> walls_by_id(const Plan& plan) {
  std::map<std::string, Wall> walls;
  for (const Wall& w : plan.walls) walls[w.id] = w;
  return walls;
}

std::vector<std::string> folder_names(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ConcurrentEdits, FourProcessesOfFiftyEditsLoseNone) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  ASSERT_TRUE(test::write_bytes(plan, write_plan_text(empty_site())));
  std::vector<EditScript> scripts;
  std::map<std::string, Wall> expected;
  for (int k = 0; k < kProcesses; ++k) {
    scripts.push_back(make_script(k, kEditsEach));
    for (const char* verb : {"add", "move", "set", "rm"})
      ASSERT_GT(scripts.back().counts[verb], 0) << "process " << k << " never runs " << verb;
    expected.insert(scripts.back().walls.begin(), scripts.back().walls.end());
  }
  std::vector<pid_t> children;
  for (int k = 0; k < kProcesses; ++k)
    children.push_back(run_script_in_child(plan, scripts[k], dir / fmt::format("log-{}", k)));
  for (int k = 0; k < kProcesses; ++k) {
    int status = 0;
    ::waitpid(children[k], &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
        << "process " << k << ": " << test::read_bytes(dir / fmt::format("log-{}", k));
    fs::remove(dir / fmt::format("log-{}", k));
  }
  const Result<Plan> result = read_plan_file(plan);
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_TRUE(validate(result.value()).ok());
  EXPECT_EQ(test::read_bytes(plan), write_plan_text(result.value()));  // canonical, whole
  const std::map<std::string, Wall> found = walls_by_id(result.value());
  EXPECT_EQ(found.size(), result.value().walls.size()) << "an id is there twice";
  for (const auto& [id, wall] : expected) {
    const auto it = found.find(id);
    if (it == found.end()) {
      ADD_FAILURE() << "lost: " << id;
      continue;
    }
    EXPECT_EQ(it->second.from, wall.from) << id;
    EXPECT_EQ(it->second.to, wall.to) << id;
    EXPECT_EQ(it->second.height, wall.height) << id;
    EXPECT_EQ(it->second.color, wall.color) << id;
    EXPECT_EQ(it->second.thickness, wall.thickness) << id;
  }
  for (const auto& [id, wall] : found) EXPECT_TRUE(expected.count(id)) << "should be gone: " << id;
  EXPECT_EQ(folder_names(dir.path()),
            std::vector<std::string>{"plan.json"});  // no lock, no temporary
}

/// Starts `roomcad args...` with its output thrown away. @return its pid.
pid_t spawn_roomcad(const std::vector<std::string>& args) {
  const std::string exe = test::roomcad_exe();
  std::vector<char*> argv{const_cast<char*>(exe.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

/// A plan of `n` separate walls w0, w1, ... (large enough that an edit takes tens of ms, most
/// of it with the lock held).
Plan many_walls(int n) {
  Plan plan;
  plan.site.cells = {100, 1 + n / 60};
  for (int i = 0; i < n; ++i) {
    Wall& w = plan.walls.emplace_back();
    w.id = fmt::format("w{}", i);
    w.from = {0.5 + 1.5 * (i % 60), 0.5 + (i / 60)};
    w.to = {w.from.x + 1, w.from.y};
    w.thickness = 0.1;
  }
  return plan;
}

TEST(ConcurrentEdits, KilledEditorsLeaveAWholePlanAndNoLockThatBlocks) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  Plan state = many_walls(600);
  ASSERT_TRUE(test::write_bytes(plan, write_plan_text(state)));
  // How long one edit takes here: kills land anywhere from its start to a little after its end.
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(test::run_roomcad({"set", plan.string(), "w0", "height=2.5"}).status, 0);
  const auto edit_us = std::chrono::duration_cast<std::chrono::microseconds>(
                           std::chrono::steady_clock::now() - start)
                           .count();
  state.walls[0].height = 2.5;
  std::mt19937 random(17);
  int old_kept = 0, new_written = 0;
  for (int round = 1; round <= 24; ++round) {
    const std::string id = fmt::format("w{}", round);
    const std::string before = write_plan_text(state);
    state.walls[round].height = 2.0 + round / 100.0;
    const std::string after = write_plan_text(state);
    const std::vector<std::string> edit{"set", plan.string(), id,
                                        fmt::format("height={}", state.walls[round].height)};
    const auto delay = std::chrono::microseconds(random() % (edit_us * 11 / 10 + 1));
    const pid_t editor = spawn_roomcad(edit);
    std::this_thread::sleep_for(delay);
    ::kill(editor, SIGKILL);
    ::waitpid(editor, nullptr, 0);
    const std::string found = test::read_bytes(plan);
    ASSERT_TRUE(found == before || found == after)
        << "round " << round << ", killed after " << delay.count()
        << " us: the plan is neither the "
        << "old one nor the new one";
    ++(found == before ? old_kept : new_written);
    // The next editor is not blocked by whatever the killed one left (--wait 2 s, for a lock
    // held by nobody), and finishes the edit if the killed one did not.
    std::vector<std::string> again = edit;
    again.insert(again.end(), {"--wait", "2"});
    const test::CommandResult r = test::run_roomcad(again);
    ASSERT_EQ(r.status, 0) << "round " << round << ": " << r.err;
    ASSERT_EQ(test::read_bytes(plan), after) << "round " << round;
  }
  std::cout << "killed editors: " << old_kept << " left the old plan, " << new_written
            << " the new one (an edit takes " << edit_us / 1000 << " ms here)\n";
  EXPECT_EQ(folder_names(dir.path()),
            std::vector<std::string>{"plan.json"});  // nothing left behind
  EXPECT_TRUE(validate(read_plan_file(plan).value()).ok());
}

}  // namespace
}  // namespace roomcad
