// The plan a window edits: selection, edits in grid steps, undo, validated saving and reloading
// when the file changes on disk. Free of SDL and of rendering, so every behaviour is tested
// without a window.
//
// Every edit goes through modeling/plan_edit.h on a copy of the plan; the plan is then
// validated, and the errors the edit introduces (validation/report_diff.h, as the edit
// commands judge them) are named in the message. Unlike the edit commands the window keeps
// such an edit, so that it can be seen (its objects drawn red) and undone or repaired; saving
// is what refuses a plan with errors.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "modeling/plan.h"
#include "modeling/plan_edit.h"
#include "validation/report.h"

namespace roomcad {

/// Most plan states kept for undo; older ones are dropped.
inline constexpr std::size_t kMaxUndo = 200;

class ViewSession {
 public:
  /// Reads and validates the plan file `path`.
  /// @return the session, or the reading errors (file, line, field and value) as text.
  [[nodiscard]] static Result<ViewSession> open(const std::filesystem::path& path);

  [[nodiscard]] const Plan& plan() const { return plan_; }
  [[nodiscard]] const Report& report() const { return report_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// Changes whenever the plan does (edit, undo, reload): the window rebuilds its model then.
  [[nodiscard]] std::uint64_t revision() const { return revision_; }
  /// The last thing done or refused, one line for the screen ("" at first).
  [[nodiscard]] const std::string& message() const { return message_; }
  [[nodiscard]] const std::optional<std::string>& selected() const { return selected_; }
  /// True when the plan differs from the file's last saved or loaded content.
  [[nodiscard]] bool is_modified() const { return modified_; }
  [[nodiscard]] std::size_t undo_depth() const { return undo_.size(); }

  /// @return the ids named by the current report's errors (drawn red), sorted, unique.
  [[nodiscard]] std::vector<std::string> error_objects() const;
  /// @return lines describing the selection: kind and id, then its fields; empty without one.
  [[nodiscard]] std::vector<std::string> selection_properties() const;

  /// Selects an object by id (nullopt: none). An id the plan lacks selects nothing.
  void select(std::optional<std::string> id);
  /// Selects the next object in plan order (walls, openings, lights, cameras), wrapping.
  void select_next();

  /// Moves the selection by whole site cells (dx east, dy north); an opening slides along its
  /// wall by dx cells (dy if dx is 0). @return true if the plan changed.
  bool move_selection(int dx_cells, int dy_cells);
  /// Turns the selection counter-clockwise by `degrees` (plan_edit's rotate_object).
  bool rotate_selection(double degrees);
  /// Deletes the selection. A wall with openings is refused with a message the first time;
  /// a second delete of the same wall in a row deletes it with its openings.
  bool delete_selection();
  /// Restores the plan before the last change. @return false when there is nothing to undo.
  bool undo();
  /// Validates and, without errors, writes the canonical file atomically.
  /// @return true if written; with errors nothing is written and the message says why.
  bool save();
  /// Re-reads the file if its modification time changed since it was last read or written.
  /// A file that does not read as a plan is reported and the plan shown is kept.
  /// @return true if the plan changed. O(1) when the file is unchanged.
  bool reload_if_changed();

 private:
  ViewSession() = default;
  using Edit = std::function<EditSummary(Plan&)>;
  /// Applies `edit` to a copy; on PreconditionError keeps the plan and shows the reason.
  bool apply(std::string_view what, const Edit& edit);
  /// Makes `next` the plan (pushing the old one for undo) and validates it.
  void replace_plan(Plan next);
  void set_message(std::string text);

  std::filesystem::path path_;
  Plan plan_;
  Report report_;
  std::vector<Plan> undo_;
  std::optional<std::string> selected_;
  std::optional<std::string> pending_cascade_;  ///< wall whose delete awaits confirmation
  std::filesystem::file_time_type file_time_{};
  std::string message_;
  std::uint64_t revision_ = 0;
  bool modified_ = false;
};

}  // namespace roomcad
