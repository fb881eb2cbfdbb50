// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/plan_lock.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace roomcad {
namespace {

using Clock = std::chrono::steady_clock;

/// The longest pause between two tries: a waiter notices a released lock within this.
constexpr std::chrono::milliseconds kLongestPause{20};
/// Times in a row a lock may be taken on a lock file its holder has just removed before
/// giving up: each needs another editor to take and release the lock meanwhile.
constexpr int kMostReopens = 1000;

/// True when `fd` is the file named `path` now, i.e. the lock file was not removed by its
/// holder (and perhaps made anew by another editor) since `fd` was opened.
bool is_current(int fd, const std::filesystem::path& path) {
  struct stat opened {};
  struct stat named {};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 &&
         opened.st_dev == named.st_dev && opened.st_ino == named.st_ino;
}

/// Opens (creating) the lock file; read-only when it is someone else's file this user may not
/// write (a flock needs no write access; the holder is then just not recorded).
int open_lock_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd >= 0 || errno != EACCES) return fd;
  return ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
}

/// Tries to lock `fd` until `deadline`, pausing 1 ms, 2 ms, ... up to kLongestPause between tries.
/// @return 0 when locked, EWOULDBLOCK when another still holds it at the deadline, else errno.
int lock_until(int fd, Clock::time_point deadline) {
  std::chrono::milliseconds pause{1};
  for (;;) {
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) return 0;
    if (errno == EINTR) continue;
    if (errno != EWOULDBLOCK) return errno;
    const Clock::time_point now = Clock::now();
    if (now >= deadline) return EWOULDBLOCK;
    std::this_thread::sleep_for(std::min<Clock::duration>(pause, deadline - now));
    pause = std::min(pause * 2, kLongestPause);
  }
}

/// Writes "<pid> <command>\n" as the lock file's whole content (over the record a killed
/// holder left, then cut to its length: a reader reads only the first line). Not truncated to
/// 0 first: ext4 then flushes the file at close (auto_da_alloc), which made each lock cost
/// milliseconds. Best effort: a holder that cannot record itself is only not named to waiters.
void record_holder(int fd, std::string_view command) {
  const std::string line = fmt::format("{} {}\n", ::getpid(), command);
  if (::pwrite(fd, line.data(), line.size(), 0) == static_cast<ssize_t>(line.size()))
    (void)!::ftruncate(fd, static_cast<off_t>(line.size()));
}

bool is_alive(long pid) {
  return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

/// "pid 1234, roomcad view" or "holder unknown".
std::string holder_text(const std::filesystem::path& plan) {
  const std::optional<LockHolder> holder = recorded_lock_holder(plan);
  if (!holder) return "holder unknown";
  return fmt::format("pid {}, {}", holder->pid, holder->command);
}

Error lock_failure(const std::filesystem::path& plan, const std::filesystem::path& lock_file,
                   std::string_view what, int error) {
  return {Code::io_error, fmt::format("cannot lock {}: {} its lock file {}: {}", plan.string(),
                                      what, lock_file.string(), std::strerror(error))};
}

}  // namespace

std::filesystem::path lock_file_of(const std::filesystem::path& plan) {
  std::string leaf = plan.filename().string();
  leaf.insert(leaf.begin(), '.');  // insert, not operator+: GCC 12 warns falsely there
  leaf.append(".lock");
  return plan.has_parent_path() ? plan.parent_path() / leaf : std::filesystem::path(leaf);
}

std::optional<LockHolder> recorded_lock_holder(const std::filesystem::path& plan) {
  const int fd = ::open(lock_file_of(plan).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::array<char, 512> buffer{};
  const ssize_t n = ::read(fd, buffer.data(), buffer.size());
  ::close(fd);
  if (n <= 0) return std::nullopt;
  const std::string_view text(buffer.data(), static_cast<std::size_t>(n));
  const std::size_t space = text.find(' ');
  const std::size_t line_end = text.find('\n');
  if (space == std::string_view::npos || line_end == std::string_view::npos || space > line_end)
    return std::nullopt;
  LockHolder holder;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + space, holder.pid);
  if (ec != std::errc{} || end != text.data() + space || !is_alive(holder.pid)) return std::nullopt;
  holder.command = std::string(text.substr(space + 1, line_end - space - 1));
  return holder;
}

Result<PlanLock> PlanLock::acquire(const std::filesystem::path& plan,
                                   std::chrono::milliseconds wait, std::string_view command) {
  const std::filesystem::path path = lock_file_of(plan);
  const Clock::time_point deadline = Clock::now() + std::max(wait, std::chrono::milliseconds(0));
  for (int reopens = 0; reopens <= kMostReopens; ++reopens) {
    const int fd = open_lock_file(path);
    if (fd < 0) return lock_failure(plan, path, "cannot create", errno);
    const int taken = lock_until(fd, deadline);
    if (taken == 0 && is_current(fd, path)) {
      record_holder(fd, command);
      return PlanLock(fd, path);
    }
    ::close(fd);
    if (taken == EWOULDBLOCK)
      return Error{
          Code::lock_timeout,
          fmt::format("{} is locked by another editor ({}), {}", plan.string(), holder_text(plan),
                      wait.count() > 0 ? fmt::format("which did not release it within {:g} s",
                                                     wait.count() / 1000.0)
                                       : std::string("and no wait was asked for"))};
    if (taken != 0) return lock_failure(plan, path, "cannot lock", taken);
    // Locked a lock file its last holder had removed: lock the one that is there now.
  }
  return Error{Code::io_error, fmt::format("cannot lock {}: its lock file {} was replaced {} times "
                                           "in a row",
                                           plan.string(), path.string(), kMostReopens)};
}

PlanLock::PlanLock(PlanLock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), lock_file_(std::move(other.lock_file_)) {}

PlanLock& PlanLock::operator=(PlanLock&& other) noexcept {
  if (this != &other) {
    release();
    fd_ = std::exchange(other.fd_, -1);
    lock_file_ = std::move(other.lock_file_);
  }
  return *this;
}

PlanLock::~PlanLock() { release(); }

void PlanLock::release() {
  if (fd_ < 0) return;
  // Removed while still locked, so an editor waiting on this file sees it is gone and opens the
  // next one; only the holder removes it, so while it is locked it is this lock's file.
  if (is_current(fd_, lock_file_)) ::unlink(lock_file_.c_str());
  ::close(fd_);
  fd_ = -1;
}

}  // namespace roomcad
