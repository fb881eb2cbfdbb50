// SPDX-License-Identifier: GPL-3.0-or-later
// ViewSession and its file on disk: opening, saving under the plan's lock, noticing changes
// other editors make, and the conflict between those and the window's unsaved edits.
#include <utility>

#include <fmt/format.h>
#include <sys/stat.h>

#include "io/plan_json.h"
#include "io/text_file.h"
#include "validation/report_format.h"
#include "validation/validate.h"
#include "view/view_session.h"

namespace roomcad {
namespace {

/// What the window records as the lock's holder, for a waiting editor's message.
constexpr std::string_view kLockHolder = "roomcad view";

/// What reading a file that is not a plan found, as text.
std::string reading_failure(const std::filesystem::path& path, const Report& report) {
  return fmt::format("{}: {}\n{}", path.string(), format_report_summary(report),
                     format_report_text(report, false));
}

std::int64_t nanoseconds(const timespec& t) {
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

}  // namespace

ViewSession::FileStamp ViewSession::stamp_of(const std::filesystem::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return {};
  return {.device = info.st_dev,
          .inode = info.st_ino,
          .size = static_cast<std::uint64_t>(info.st_size),
          .modified_ns = nanoseconds(info.st_mtim),
          .changed_ns = nanoseconds(info.st_ctim),
          .exists = true};
}

Result<ViewSession> ViewSession::open(const std::filesystem::path& path,
                                      std::chrono::milliseconds lock_wait) {
  const FileStamp stamp = stamp_of(path);  // before reading: a change meanwhile is seen later
  Result<std::string> text = read_text_file(path);
  if (!text) return text.error();
  Report report;
  Result<Plan> read = read_plan_text(text.value(), path.string(), &report);
  if (!read) return Error{read.code(), reading_failure(path, report), read.error().location};
  ViewSession session;
  session.path_ = path;
  session.lock_wait_ = lock_wait;
  session.stamp_ = stamp;
  session.plan_ = read.value();
  session.report_ = validate(session.plan_);
  session.set_base(std::move(text).value(), std::move(read).value());
  return session;
}

void ViewSession::set_base(std::string text, Plan plan) {
  base_text_ = std::move(text);
  base_plan_ = std::move(plan);
  modified_ = plan_ != base_plan_;
  conflict_.reset();
}

std::optional<std::string> ViewSession::read_disk() const {
  Result<std::string> text = read_text_file(path_);
  if (!text) return std::nullopt;
  return std::move(text).value();
}

bool ViewSession::is_known(const std::optional<std::string>& disk_text) const {
  return conflict_ ? disk_text == conflict_->disk_text : disk_text == base_text_;
}

void ViewSession::show_conflict(std::optional<std::string> disk_text, std::string_view why) {
  if (!is_known(disk_text)) ++disk_changes_;
  const bool is_plan = disk_text && read_plan_text(*disk_text, path_.string()).ok();
  conflict_ = Conflict{std::move(disk_text)};
  set_message(
      fmt::format("{}{}: Ctrl+R loads the file (dropping the window's edits; Ctrl+Z "
                  "brings them back), Ctrl+K keeps the window's version (saving it over "
                  "the file)",
                  why, is_plan ? "" : " (it is not a valid plan now)"));
}

bool ViewSession::load(std::string text, Plan plan, std::string message) {
  const bool changed = plan != plan_;
  set_base(std::move(text), plan);
  if (changed) replace_plan(std::move(plan));  // undoable, as any change of the plan shown
  set_message(std::move(message));
  return changed;
}

Status ViewSession::check_savable() {
  report_ = validate(plan_);
  if (report_.ok()) return Status::success();
  return refuse(Code::edit_refused,
                fmt::format("not saved: the plan has {} (in red); fix or undo (Ctrl+Z) first",
                            format_report_summary(report_)));
}

Status ViewSession::write_locked() {
  std::string text = write_plan_text(plan_);
  const Status written = write_plan_file(plan_, path_);
  stamp_ = stamp_of(path_);
  // A write that failed after its rename (the folder not flushed) did replace the file.
  const bool in_place = written || read_disk() == text;
  if (in_place) set_base(std::move(text), plan_);
  set_message(written    ? fmt::format("saved {}", path_.string())
              : in_place ? fmt::format("saved, but: {}", written.message())
                         : fmt::format("not saved: {}", written.message()));
  return written;
}

Status ViewSession::save_over(std::optional<std::string_view> expected, std::string_view changed,
                              std::string_view key) {
  if (Status savable = check_savable(); !savable) return savable;
  const Result<PlanLock> lock = PlanLock::acquire(path_, lock_wait_, kLockHolder);
  if (!lock)
    return refuse(lock.code(), fmt::format("not saved: {}; {} tries again", lock.message(), key));
  std::optional<std::string> disk = read_disk();
  if (disk ? !expected || *disk != *expected : expected.has_value()) {
    show_conflict(std::move(disk), fmt::format("not saved: {} {}", path_.string(), changed));
    return Status::failure(Code::edit_refused, message_);
  }
  return write_locked();
}

Status ViewSession::save() {
  pending_cascade_.reset();
  constexpr std::string_view kChanged = "changed on disk since the window read or saved it";
  if (conflict_) {  // the choice is still to be made
    show_conflict(read_disk(), fmt::format("not saved: {} {}", path_.string(), kChanged));
    return Status::failure(Code::edit_refused, message_);
  }
  return save_over(base_text_, kChanged, "Ctrl+S");
}

Status ViewSession::keep_window_version() {
  pending_cascade_.reset();
  if (!conflict_)
    return refuse(Code::usage_error,
                  "nothing to keep: the file has not changed on disk (Ctrl+S saves)");
  return save_over(conflict_->disk_text, "changed on disk again", "Ctrl+K");
}

Status ViewSession::reload_file() {
  pending_cascade_.reset();
  stamp_ = stamp_of(path_);
  Result<std::string> text = read_text_file(path_);
  if (!text) return refuse(text.code(), fmt::format("not reloaded: {}", text.message()));
  Result<Plan> read = read_plan_text(text.value(), path_.string());
  if (!read)
    return refuse(read.code(), fmt::format("not reloaded: {} is not a valid plan ({}: {})",
                                           path_.string(), to_string(read.code()), read.message()));
  const bool dropped = modified_;
  load(std::move(text).value(), std::move(read).value(),
       fmt::format("reloaded {}{}", path_.string(),
                   dropped ? " (the window's edits dropped; Ctrl+Z brings them back)" : ""));
  return Status::success();
}

Result<bool> ViewSession::reload_if_changed() {
  const FileStamp stamp = stamp_of(path_);
  if (stamp == stamp_) return false;
  stamp_ = stamp;
  std::optional<std::string> disk = read_disk();
  if (is_known(disk)) return false;       // touched, or rewritten with the same bytes
  if (conflict_ && disk == base_text_) {  // changed back: the window's edits apply again
    ++disk_changes_;
    conflict_.reset();
    set_message(fmt::format("{} on disk is back to the version the window loaded; Ctrl+S saves",
                            path_.string()));
    return false;
  }
  if (modified_ || conflict_) {
    show_conflict(std::move(disk), fmt::format("{} changed on disk and the window has unsaved "
                                               "edits",
                                               path_.string()));
    return false;
  }
  ++disk_changes_;
  if (!disk)
    return refuse(Code::io_error,
                  fmt::format("{} cannot be read now; the plan shown is kept", path_.string()))
        .error();
  Result<Plan> read = read_plan_text(*disk, path_.string());
  if (!read)
    return refuse(read.code(),
                  fmt::format("{} changed on disk but is not a valid plan ({}: {}); the plan "
                              "shown is kept",
                              path_.string(), to_string(read.code()), read.message()))
        .error();
  return load(std::move(*disk), std::move(read).value(),
              fmt::format("reloaded {} (changed on disk; Ctrl+Z goes back)", path_.string()));
}

}  // namespace roomcad
