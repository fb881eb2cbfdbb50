// SPDX-License-Identifier: GPL-3.0-or-later
// The plan a window edits: selection, edits in grid steps, undo, validated saving and reloading
// when the file changes on disk. Free of SDL and of rendering, so every behaviour is tested
// without a window.
//
// Every edit goes through plan/plan_edit.h on a copy of the plan; the plan is then
// validated, and the errors the edit introduces (validation/report_diff.h, as the edit
// commands judge them) are named in the message. Unlike the edit commands the window keeps
// such an edit, so that it can be seen (its objects drawn red) and undone or repaired; saving
// is what refuses a plan with errors.
//
// The file on disk: the session remembers the bytes its edits start from (the file as last
// loaded or saved). Saving takes the plan's lock (io/plan_lock.h) and writes only if the file
// still holds those bytes. When the file changed on disk, the session reloads it if the window
// holds no unsaved edits; otherwise it never overwrites nor drops either side silently: it
// enters a conflict, names both choices in its message and saves nothing until one is made,
// reload_file() (the file's version, the window's edits dropped but kept for undo) or
// keep_window_version() (the window's version saved over the file it was shown).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "io/plan_lock.h"
#include "plan/plan.h"
#include "plan/plan_edit.h"
#include "validation/report.h"

namespace roomcad {

/// Most plan states kept for undo; older ones are dropped.
inline constexpr std::size_t kMaxUndo = 200;

class ViewSession {
 public:
  /// Reads and validates the plan file `path`.
  /// @param lock_wait  how long a save waits for another editor's lock of the plan
  /// @return the session, or the reading errors (file, line, field and value) as text.
  [[nodiscard]] static Result<ViewSession> open(
      const std::filesystem::path& path, std::chrono::milliseconds lock_wait = kDefaultLockWait);

  [[nodiscard]] const Plan& plan() const { return plan_; }
  [[nodiscard]] const Report& report() const { return report_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// Changes whenever the plan does (edit, undo, reload): the window rebuilds its model then.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }
  /// The last thing done or refused, one line for the screen ("" at first).
  [[nodiscard]] const std::string& message() const { return message_; }
  /// How many messages were given so far (a log prints each once, even one repeated).
  [[nodiscard]] std::uint64_t message_count() const { return message_count_; }
  [[nodiscard]] const std::optional<std::string>& selected() const { return selected_; }
  /// True when the plan differs from the file as last loaded or saved: unsaved edits.
  [[nodiscard]] bool is_modified() const { return modified_; }
  /// True while the file changed on disk and the window holds unsaved edits (or tried to save
  /// over the change): nothing is saved until reload_file() or keep_window_version().
  [[nodiscard]] bool in_conflict() const { return conflict_.has_value(); }
  /// How many changes of the file on disk the session has found (each reload or conflict, or
  /// a file that no longer reads as a plan); `--keys wait:change` waits for this to grow.
  [[nodiscard]] std::uint64_t disk_changes() const { return disk_changes_; }
  [[nodiscard]] std::size_t undo_depth() const { return undo_.size(); }

  /// @return the ids named by the current report's errors (drawn red), sorted, unique.
  [[nodiscard]] std::vector<std::string> error_objects() const;
  /// @return lines describing the selection: kind and id, then its fields; empty without one.
  [[nodiscard]] std::vector<std::string> selection_properties() const;

  /// Selects an object by id (nullopt: none). An id the plan lacks selects nothing.
  void select(std::optional<std::string> id);
  /// Selects the next object in plan order (walls, openings, lights, cameras), wrapping.
  void select_next();

  // The actions below return success when done (the plan changed, the file written), else
  // the Error why not: usage_error (nothing selected, nothing to undo or keep), the edit's own
  // error (an edit that cannot be made: a light has no position), edit_refused (an edit that
  // changes nothing, a delete that asks first, a plan with errors or a file changed on disk
  // not saved over), lock_timeout, or the reading or writing error of the file. The window
  // shows message() either way.

  /// Moves the selection by whole site cells (dx east, dy north); an opening slides along its
  /// wall by dx cells (dy if dx is 0).
  Status move_selection(int dx_cells, int dy_cells);
  /// Turns the selection counter-clockwise by `degrees` (plan_edit's rotate_object).
  Status rotate_selection(double degrees);
  /// Deletes the selection. A wall with openings is refused with a message the first time;
  /// a second delete of the same wall in a row deletes it with its openings.
  Status delete_selection();
  /// Restores the plan before the last change.
  Status undo();
  /// Validates and, without errors, writes the canonical file atomically, holding the plan's
  /// lock from checking that the file on disk is still the one the edits start from to the
  /// rename. A file changed on disk meanwhile, or a conflict already shown, is not written
  /// over: the conflict's choices are shown instead.
  /// Not written: the plan's errors, the lock held by another editor for longer than the lock
  /// wait, the conflict, an I/O error.
  Status save();
  /// Looks at the file: if it changed on disk since it was last loaded or saved (its bytes, not
  /// only its time), reloads it when the window holds no unsaved edits, else enters (or
  /// updates) the conflict. O(1) (one stat) while the file is untouched.
  /// @return whether the plan changed; or the error of a changed file that cannot be read or
  ///         is not a valid plan (reported; the plan shown is kept).
  [[nodiscard]] Result<bool> reload_if_changed();
  /// Loads the file as it is on disk now, dropping the window's unsaved edits (undo brings
  /// them back) and ending a conflict. Not done if it cannot be read as a plan (the plan shown
  /// is kept).
  Status reload_file();
  /// In a conflict: saves the window's plan over the file, under the lock, if the file still
  /// holds the version the conflict was shown for (if it changed again the conflict is shown
  /// anew). Refused, as save() is, while the plan has errors.
  Status keep_window_version();

 private:
  ViewSession() = default;
  using Edit = std::function<Result<EditSummary>(Plan&)>;
  /// Applies `edit` to a copy; where it fails (its Error, or PreconditionError) or changes
  /// nothing, keeps the plan and shows why.
  Status apply(std::string_view what, const Edit& edit);
  /// Makes `next` the plan (pushing the old one for undo) and validates it.
  void replace_plan(Plan next);
  void set_message(std::string text);
  /// Shows `text` and @return it as the failure of an action, with `code`.
  Status refuse(Code code, std::string text);
  /// The file's version (bytes and plan) becomes what the edits start from; ends a conflict.
  void set_base(std::string text, Plan plan);
  /// Makes the file's version the base and the plan shown. @return true if the plan changed.
  bool load(std::string text, Plan plan, std::string message);
  /// Enters or updates the conflict with the file as now on disk (nullopt: unreadable); the
  /// message is `why` and the choices.
  void show_conflict(std::optional<std::string> disk_text, std::string_view why);
  /// @return true if `disk_text` is the version last seen: the conflict's, else the base.
  [[nodiscard]] bool is_known(const std::optional<std::string>& disk_text) const;
  /// Validates; with errors says so. @return success if the plan may be saved.
  Status check_savable();
  /// Validates, takes the lock and writes if the file holds `expected` (nullopt: unreadable);
  /// otherwise shows the conflict, saying the file `changed`. `key` retries after a lock
  /// timeout.
  Status save_over(std::optional<std::string_view> expected, std::string_view changed,
                   std::string_view key);
  /// Writes the plan; the caller holds the lock and has checked the file.
  Status write_locked();
  /// The file's bytes now, or nullopt when it cannot be read.
  [[nodiscard]] std::optional<std::string> read_disk() const;

  /// What identifies the file's current content cheaply (device, inode, size, times).
  struct FileStamp {
    std::uint64_t device = 0, inode = 0, size = 0;
    std::int64_t modified_ns = 0, changed_ns = 0;
    bool exists = false;
    friend bool operator==(const FileStamp&, const FileStamp&) = default;
  };
  [[nodiscard]] static FileStamp stamp_of(const std::filesystem::path& path);
  /// The file as the conflict was shown for it (nullopt: unreadable then).
  struct Conflict {
    std::optional<std::string> disk_text;
  };

  std::filesystem::path path_;
  Plan plan_;
  Report report_;
  std::vector<Plan> undo_;
  std::optional<std::string> selected_;
  std::optional<std::string> pending_cascade_;  ///< wall whose delete awaits confirmation
  std::chrono::milliseconds lock_wait_ = kDefaultLockWait;
  std::string base_text_;  ///< the file's bytes as last loaded or saved: what edits start from
  Plan base_plan_;         ///< base_text_ read as a plan
  FileStamp stamp_;        ///< the file when last looked at, for cheap polling
  std::optional<Conflict> conflict_;
  std::string message_;
  std::uint64_t message_count_ = 0;
  std::uint64_t revision_ = 0;
  std::uint64_t disk_changes_ = 0;
  bool modified_ = false;
};

}  // namespace roomcad
