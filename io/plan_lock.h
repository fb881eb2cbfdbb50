// SPDX-License-Identifier: GPL-3.0-or-later
// The lock of a plan file: every read-modify-write of a plan (the edit commands, `fmt`, the
// window's save) holds it from reading the file to renaming the new one over it, so that two
// editors never both read the same plan and the last writer never drops the other's edit.
//
// It is an exclusive flock(2) on a lock file beside the plan, `.<name>.lock` in the plan's
// folder (flock, not the plan itself: a save replaces the plan's inode by rename). The kernel
// releases a flock when its holder dies, so a process killed while holding it (SIGKILL, a
// crash) never blocks the next editor. The holder writes "<pid> <command>" into the lock file
// for the message of an editor that gives up waiting; that record is trusted only while its
// process is alive, so one left by a killed holder never names the wrong holder. The last
// holder removes the lock file when it is done (the file a killed holder leaves is reused);
// an editor that locked a file removed meanwhile opens the new one and locks again.
//
// Locks are advisory: only roomcad's editors take them. Locks of one plan reached through
// different paths of the same folder are the same lock (the same lock file); a plan reached
// through a symbolic link is locked where the link is, which is the file a save replaces.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace roomcad {

/// How long an editor waits for another's lock unless told otherwise (`--wait SECONDS`).
inline constexpr std::chrono::milliseconds kDefaultLockWait{5000};

/// Who holds a plan's lock, as the holder recorded it.
struct LockHolder {
  long pid = 0;         ///< its process id
  std::string command;  ///< what it is ("roomcad add", "roomcad view")
  friend bool operator==(const LockHolder&, const LockHolder&) = default;
};

/// @return the lock file of the plan file `plan`: `.<name>.lock` in the same folder.
[[nodiscard]] std::filesystem::path lock_file_of(const std::filesystem::path& plan);

/// @return the recorded holder of `plan`'s lock when there is one and its process is alive;
///         nullopt when the lock file is missing, empty, unreadable or names a dead process.
///         It does not tell whether the lock is held now (a holder between taking the lock and
///         writing its record is not named). Cost: one small file read.
[[nodiscard]] std::optional<LockHolder> recorded_lock_holder(const std::filesystem::path& plan);

/// An exclusive lock on one plan file, held from acquire() until it is destroyed (or the
/// process ends). Move-only; a moved-from lock holds nothing.
class PlanLock {
 public:
  /// Takes the lock of the plan file `plan` (which need not exist), waiting while another
  /// process holds it: tried at once, then every few milliseconds (1 ms doubling to 20 ms)
  /// until `wait` has passed.
  /// @param wait     how long to wait for another holder; 0 tries once
  /// @param command  what this process is, recorded for waiting editors ("roomcad add")
  /// @return the lock; Code::lock_timeout when another holder kept it for longer than `wait`
  ///         (the message names the plan, the holder if recorded and alive, and the wait);
  ///         Code::io_error when the lock file cannot be created or locked (names it, and why).
  /// Cost: an open, a flock and a small write when the lock is free.
  [[nodiscard]] static Result<PlanLock> acquire(const std::filesystem::path& plan,
                                                std::chrono::milliseconds wait,
                                                std::string_view command);

  PlanLock(PlanLock&& other) noexcept;
  PlanLock& operator=(PlanLock&& other) noexcept;
  PlanLock(const PlanLock&) = delete;
  PlanLock& operator=(const PlanLock&) = delete;
  /// Releases the lock: removes the lock file (if it is still this lock's), then closes it.
  ~PlanLock();

  [[nodiscard]] const std::filesystem::path& lock_file() const { return lock_file_; }

 private:
  PlanLock(int fd, std::filesystem::path lock_file) : fd_(fd), lock_file_(std::move(lock_file)) {}
  void release();

  int fd_ = -1;
  std::filesystem::path lock_file_;
};

}  // namespace roomcad
