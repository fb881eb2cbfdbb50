// SPDX-License-Identifier: GPL-3.0-or-later
// A save killed midway (SIGKILL: no destructor, no handler runs) leaves the old file byte for
// byte, and the temporary file it leaves is removed by the next save.
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/atomic_write.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> leaves(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// Forks a child that saves `path` with a producer writing `bytes_before_kill` bytes (more
/// than the write buffer, so part of it reaches the temporary file) and then killing itself.
/// @return the child's wait status.
int save_and_die(const fs::path& path, std::size_t bytes_before_kill) {
  const pid_t child = ::fork();
  if (child == 0) {
    (void)write_file_atomically(path, [bytes_before_kill](std::ostream& out) {
      const std::string chunk(4096, 'n');
      for (std::size_t n = 0; n < bytes_before_kill; n += chunk.size()) out << chunk;
      out.flush();
      ::raise(SIGKILL);
      return true;
    });
    ::_exit(0);  // not reached: the save must not complete
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

TEST(AtomicWrite, KilledSaveLeavesTheOldFileIntact) {
  test::TempDir dir;
  std::string old_bytes;
  for (int i = 0; i < 5000; ++i) old_bytes += "old line " + std::to_string(i) + "\n";
  ASSERT_TRUE(test::write_bytes(dir / "plan.json", old_bytes));

  const int status = save_and_die(dir / "plan.json", 1 << 20);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child was meant to die by SIGKILL, status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_EQ(test::read_bytes(dir / "plan.json"), old_bytes);
  // The dead writer's temporary file is still there, holding what it had written.
  const std::vector<std::string> after_kill = leaves(dir.path());
  ASSERT_EQ(after_kill.size(), 2u);
  EXPECT_EQ(after_kill[0].rfind(".plan.json.tmp-", 0), 0u) << after_kill[0];
  EXPECT_GT(fs::file_size(dir / after_kill[0]), 0u);

  // The next save replaces the file and removes the dead writer's temporary file.
  ASSERT_TRUE(write_file_atomically(dir / "plan.json", std::string_view("new\n")).ok());
  EXPECT_EQ(test::read_bytes(dir / "plan.json"), "new\n");
  EXPECT_EQ(leaves(dir.path()), std::vector<std::string>{"plan.json"});
}

TEST(AtomicWrite, ASaveLeavesTemporaryFilesOfLiveWritersAndOtherFilesAlone) {
  test::TempDir dir;
  // This process is alive: its (pretend) temporary file may be a save in progress.
  const std::string live = ".plan.json.tmp-" + std::to_string(::getpid()) + "-abcdef";
  ASSERT_TRUE(test::write_bytes(dir / live, "in progress"));
  ASSERT_TRUE(test::write_bytes(dir / ".plan.json.tmp-notapid", "someone else's"));
  ASSERT_TRUE(test::write_bytes(dir / ".other.json.tmp-1-abcdef", "another file's"));
  ASSERT_TRUE(write_file_atomically(dir / "plan.json", std::string_view("new\n")).ok());
  EXPECT_EQ(leaves(dir.path()), (std::vector<std::string>{".other.json.tmp-1-abcdef", live,
                                                          ".plan.json.tmp-notapid", "plan.json"}));
}

}  // namespace
}  // namespace roomcad
