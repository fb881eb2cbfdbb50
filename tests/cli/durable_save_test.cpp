// SPDX-License-Identifier: GPL-3.0-or-later
// Saves are durable (io/atomic_write.h): the new file is flushed to disk (fsync) before it is
// renamed over the plan, and the folder after the rename, as strace sees roomcad do it; a
// flush that fails (an error strace injects) is reported with exit status 2, and before the
// rename it leaves the plan as it was. strace missing is a failure, not a skip:
// scripts/setup.sh installs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/plan_json.h"
#include "support/plan_reading.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;

struct Traced {
  CommandResult result;
  std::vector<std::string> calls;  ///< the traced system calls, in order, pids removed
};

/// Runs `roomcad set PLAN south height=2.5` under strace, tracing opens, flushes and renames;
/// `inject` adds an strace -e inject=... fault.
Traced traced_set(const test::TempDir& dir, const fs::path& plan, const std::string& inject = "") {
  const fs::path log = dir / "strace.log";
  std::vector<std::string> args{"-f", "-qq",
                                "-o", log.string(),
                                "-e", "trace=openat,fsync,fdatasync,rename,renameat,renameat2"};
  if (!inject.empty()) args.insert(args.end(), {"-e", "inject=" + inject});
  // LeakSanitizer cannot run under ptrace (a sanitized build would fail at exit): off here.
  const char* asan = std::getenv("ASAN_OPTIONS");
  args.insert(args.end(), {"-E", fmt::format("ASAN_OPTIONS={}{}detect_leaks=0", asan ? asan : "",
                                             asan && *asan ? ":" : "")});
  args.insert(args.end(), {test::roomcad_exe(), "set", plan.string(), "south", "height=2.5"});
  Traced traced{test::run_program("strace", args), {}};
  std::istringstream lines(test::read_bytes(log));
  for (std::string line; std::getline(lines, line);)  // "<pid>  <call>"
    traced.calls.push_back(
        line.substr(std::min(line.size(), line.find_first_not_of(' ', line.find(' ')))));
  EXPECT_FALSE(traced.calls.empty())
      << "strace did not run (scripts/setup.sh installs it): " << traced.result.err;
  return traced;
}

/// @return `text` as a regular expression matching it literally.
std::string escaped(const std::string& text) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(text, special, R"(\$&)");
}

/// The index of the first call at or after `from` matching `pattern`, or -1; `match` gets the
/// groups.
long find_call(const std::vector<std::string>& calls, std::size_t from, const std::string& pattern,
               std::smatch* match = nullptr) {
  const std::regex re(pattern);
  for (std::size_t i = from; i < calls.size(); ++i) {
    std::smatch m;
    if (std::regex_search(calls[i], m, re)) {
      if (match) *match = m;
      return static_cast<long>(i);
    }
  }
  return -1;
}

class DurableSave : public ::testing::Test {
 protected:
  void SetUp() override {
    const test::PlanReading read =
        test::read_plan_at(test::source_dir() / "tests/cli/data/edit_room.json");
    ASSERT_TRUE(read.plan);
    original_ = write_plan_text(*read.plan);
    ASSERT_TRUE(test::write_bytes(plan_, original_));
  }
  /// The names in the plan's folder other than the plan and strace's log.
  std::vector<std::string> leftovers() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_.path()))
      if (e.path() != plan_ && e.path().filename() != "strace.log")
        names.push_back(e.path().filename().string());
    return names;
  }

  test::TempDir dir_;
  fs::path plan_ = dir_ / "plan.json";
  std::string original_;
};

TEST_F(DurableSave, TheNewFileIsFlushedBeforeTheRenameAndTheFolderAfter) {
  const Traced t = traced_set(dir_, plan_);
  ASSERT_EQ(t.result.status, 0) << t.result.err;
  std::smatch m;
  const long created = find_call(
      t.calls, 0, R"re(openat\(.*"(.*/\.plan\.json\.tmp-[^"]*)".*O_CREAT.* = (\d+))re", &m);
  ASSERT_GE(created, 0) << "no temporary file was created";
  const std::string temporary = m[1], file_fd = m[2];
  const long file_sync = find_call(t.calls, created, "^fsync\\(" + file_fd + "\\) += 0");
  const long renamed = find_call(
      t.calls, created,
      "rename.*\"" + escaped(temporary) + "\", .*\"" + escaped(plan_.string()) + "\"\\) += 0");
  ASSERT_GE(file_sync, 0) << "the new file was not flushed";
  ASSERT_GE(renamed, 0) << "the new file was not renamed over the plan";
  EXPECT_LT(file_sync, renamed);
  const long folder = find_call(
      t.calls, renamed,
      "openat\\(.*\"" + escaped(dir_.path().string()) + "\", .*O_DIRECTORY.* = (\\d+)", &m);
  ASSERT_GE(folder, 0) << "the folder was not opened after the rename";
  EXPECT_GE(find_call(t.calls, folder, "^fsync\\(" + std::string(m[1]) + "\\) += 0"), 0)
      << "the folder was not flushed after the rename";
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(DurableSave, AFailedFileFlushLeavesThePlanAsItWas) {
  const Traced t = traced_set(dir_, plan_, "fsync:error=EIO:when=1");
  EXPECT_EQ(t.result.status, 2) << t.result.err;
  EXPECT_EQ(test::failure_code(t.result), Code::io_error) << t.result.err;
  EXPECT_NE(
      t.result.err.find("cannot write " + plan_.string() + ": write failed: Input/output error"),
      std::string::npos)
      << t.result.err;
  EXPECT_EQ(test::read_bytes(plan_), original_);
  EXPECT_TRUE(leftovers().empty());  // neither the temporary file nor the lock file
}

TEST_F(DurableSave, AFailedFolderFlushIsReported) {
  const Traced t = traced_set(dir_, plan_, "fsync:error=EIO:when=2");
  EXPECT_EQ(t.result.status, 2) << t.result.err;
  EXPECT_EQ(test::failure_code(t.result), Code::io_error) << t.result.err;
  EXPECT_NE(t.result.err.find("the new file is in place, but its folder could not be flushed"),
            std::string::npos)
      << t.result.err;
  EXPECT_NE(t.result.err.find("Input/output error"), std::string::npos) << t.result.err;
  const Plan written = read_plan_file(plan_).value();
  EXPECT_EQ(written.walls[0].height, 2.5);  // renamed: the new plan, not yet safe from a power cut
  EXPECT_TRUE(leftovers().empty());
}

}  // namespace
}  // namespace roomcad
