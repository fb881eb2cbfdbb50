// SPDX-License-Identifier: GPL-3.0-or-later
// The plan lock: exclusive across open files (flock locks an open file, so two acquires in one
// process exclude each other as two processes do), waits, gives up with lock_timeout naming the
// plan and the holder, never trusts a dead holder's record, and never blocks after its holder
// was killed.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/plan_lock.h"
#include "support/run_command.h"

namespace roomcad {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

/// @return the id of a process that has ended (and been reaped).
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

/// A lock taken with flock directly: a holder that has not (yet) recorded itself.
struct RawFlock {
  int fd;
  explicit RawFlock(const fs::path& path) : fd(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
    EXPECT_GE(fd, 0);
    EXPECT_EQ(::flock(fd, LOCK_EX), 0);
  }
  ~RawFlock() { ::close(fd); }
};

TEST(PlanLock, LockFileIsBesideThePlan) {
  EXPECT_EQ(lock_file_of("some/dir/plan.json"), fs::path("some/dir/.plan.json.lock"));
  EXPECT_EQ(lock_file_of("plan.json"), fs::path(".plan.json.lock"));
}

TEST(PlanLock, IsExclusiveAndNamesTheHolder) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  Result<PlanLock> first = PlanLock::acquire(plan, milliseconds(0), "roomcad add");
  ASSERT_TRUE(first.ok()) << first.error();
  EXPECT_TRUE(fs::exists(dir / ".plan.json.lock"));
  EXPECT_EQ(recorded_lock_holder(plan), (LockHolder{::getpid(), "roomcad add"}));

  const auto start = std::chrono::steady_clock::now();
  const Result<PlanLock> second = PlanLock::acquire(plan, milliseconds(150), "roomcad move");
  const auto waited = std::chrono::steady_clock::now() - start;
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.code(), Code::lock_timeout);
  EXPECT_GE(waited, milliseconds(150));
  EXPECT_NE(second.message().find(plan.string()), std::string::npos) << second.message();
  EXPECT_NE(second.message().find("pid " + std::to_string(::getpid()) + ", roomcad add"),
            std::string::npos)
      << second.message();
  EXPECT_NE(second.message().find("0.15 s"), std::string::npos) << second.message();
}

TEST(PlanLock, ReleaseRemovesTheLockFileAndFreesTheLock) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  {
    Result<PlanLock> held = PlanLock::acquire(plan, milliseconds(0), "a");
    ASSERT_TRUE(held.ok());
    PlanLock moved = std::move(held).value();  // the moved-from lock releases nothing
    EXPECT_FALSE(PlanLock::acquire(plan, milliseconds(0), "b").ok());
  }
  EXPECT_FALSE(fs::exists(dir / ".plan.json.lock"));
  EXPECT_TRUE(PlanLock::acquire(plan, milliseconds(0), "c").ok());
}

TEST(PlanLock, AWaiterGetsTheLockWhenItIsReleased) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  std::optional<PlanLock> held = PlanLock::acquire(plan, milliseconds(0), "first").value();
  std::thread release([&] {
    std::this_thread::sleep_for(milliseconds(200));
    held.reset();
  });
  const auto start = std::chrono::steady_clock::now();
  const Result<PlanLock> waited = PlanLock::acquire(plan, milliseconds(20000), "second");
  const auto took = std::chrono::steady_clock::now() - start;
  release.join();
  ASSERT_TRUE(waited.ok()) << waited.error();
  EXPECT_GE(took, milliseconds(150));
  EXPECT_LT(took, milliseconds(10000));
  EXPECT_EQ(recorded_lock_holder(plan), (LockHolder{::getpid(), "second"}));
}

TEST(PlanLock, AKilledHolderNeverBlocksAndIsNotNamed) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  const pid_t child = ::fork();
  if (child == 0) {
    const Result<PlanLock> lock = PlanLock::acquire(plan, milliseconds(0), "roomcad add");
    if (lock.ok()) ::raise(SIGKILL);  // dies holding it: no destructor runs
    ::_exit(1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child could not take the lock";
  // Its lock file and record are left, and the record is not trusted: the process is gone.
  EXPECT_EQ(test::read_bytes(dir / ".plan.json.lock"), std::to_string(child) + " roomcad add\n");
  EXPECT_EQ(recorded_lock_holder(plan), std::nullopt);
  const Result<PlanLock> next = PlanLock::acquire(plan, milliseconds(0), "roomcad set");
  ASSERT_TRUE(next.ok()) << next.error();
  EXPECT_EQ(recorded_lock_holder(plan), (LockHolder{::getpid(), "roomcad set"}));
}

TEST(PlanLock, AStaleRecordDoesNotNameTheWrongHolder) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  ASSERT_TRUE(
      test::write_bytes(dir / ".plan.json.lock", std::to_string(dead_pid()) + " roomcad rm\n"));
  const RawFlock holder(dir / ".plan.json.lock");  // locked, but not (yet) recorded
  const Result<PlanLock> lock = PlanLock::acquire(plan, milliseconds(0), "roomcad add");
  ASSERT_FALSE(lock.ok());
  EXPECT_EQ(lock.code(), Code::lock_timeout);
  EXPECT_NE(lock.message().find("holder unknown"), std::string::npos) << lock.message();
  EXPECT_EQ(lock.message().find("roomcad rm"), std::string::npos) << lock.message();
}

TEST(PlanLock, AWaiterOnARemovedLockFileLocksTheNewOne) {
  test::TempDir dir;
  const fs::path plan = dir / "plan.json";
  const fs::path lock_file = dir / ".plan.json.lock";
  auto holder = std::make_unique<RawFlock>(lock_file);
  std::optional<Result<PlanLock>> waited;
  std::thread waiter([&] { waited = PlanLock::acquire(plan, milliseconds(20000), "waiter"); });
  std::this_thread::sleep_for(milliseconds(100));  // the waiter has opened the old file
  struct stat old_file {};
  ASSERT_EQ(::fstat(holder->fd, &old_file), 0);
  const int keep_old = ::dup(holder->fd);     // keeps its inode number from being reused
  ASSERT_EQ(::unlink(lock_file.c_str()), 0);  // what a releasing holder does, then unlocks
  ASSERT_EQ(::flock(holder->fd, LOCK_UN), 0);
  waiter.join();
  ::close(keep_old);
  holder.reset();
  ASSERT_TRUE(waited && waited->ok());
  struct stat new_file {};
  ASSERT_EQ(::stat(lock_file.c_str(), &new_file), 0);
  EXPECT_NE(new_file.st_ino, old_file.st_ino);
  EXPECT_EQ(recorded_lock_holder(plan), (LockHolder{::getpid(), "waiter"}));
  EXPECT_EQ(PlanLock::acquire(plan, milliseconds(0), "third").code(), Code::lock_timeout);
}

TEST(PlanLock, AMissingFolderIsAnIoErrorNamingThePlanAndTheLockFile) {
  test::TempDir dir;
  const fs::path plan = dir / "no" / "plan.json";
  const Result<PlanLock> lock = PlanLock::acquire(plan, milliseconds(0), "roomcad add");
  ASSERT_FALSE(lock.ok());
  EXPECT_EQ(lock.code(), Code::io_error);
  EXPECT_NE(lock.message().find(plan.string()), std::string::npos) << lock.message();
  EXPECT_NE(lock.message().find(".plan.json.lock"), std::string::npos) << lock.message();
  EXPECT_NE(lock.message().find("No such file or directory"), std::string::npos) << lock.message();
}

}  // namespace
}  // namespace roomcad
