// SPDX-License-Identifier: GPL-3.0-or-later
#include "view/view_session.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "solid/build_model.h"
#include "validation/report_diff.h"
#include "validation/report_format.h"
#include "validation/validate.h"
#include "view/object_properties.h"

namespace roomcad {
namespace {

/// The ids the window's Tab steps through, in plan order: walls, openings, lights, cameras.
std::vector<std::string> selectable_ids(const Plan& plan) {
  std::vector<std::string> ids;
  for (const Wall& w : plan.walls) ids.push_back(w.id);
  for (const Opening& o : plan.openings) ids.push_back(o.id);
  for (const Light& l : plan.lights) ids.push_back(l.id);
  for (const Camera& c : plan.cameras) ids.push_back(c.id);
  return ids;
}

/// "1 error" or "N errors".
std::string error_count(const Report& report) {
  const std::size_t n = report.error_count();
  return fmt::format("{} error{}", n, n == 1 ? "" : "s");
}

}  // namespace

std::vector<std::string> ViewSession::error_objects() const {
  std::vector<std::string> ids;
  for (const Diagnostic& d : report_.items)
    if (d.severity == Severity::error) ids.insert(ids.end(), d.objects.begin(), d.objects.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

std::vector<std::string> ViewSession::selection_properties() const {
  return selected_ ? describe_object(plan_, *selected_) : std::vector<std::string>{};
}

void ViewSession::select(std::optional<std::string> id) {
  pending_cascade_.reset();
  if (id && !object_kind(plan_, *id)) id.reset();
  selected_ = std::move(id);
}

void ViewSession::select_next() {
  const std::vector<std::string> ids = selectable_ids(plan_);
  if (ids.empty()) return select(std::nullopt);
  auto it = selected_ ? std::find(ids.begin(), ids.end(), *selected_) : ids.end();
  select(it == ids.end() || it + 1 == ids.end() ? ids.front() : *(it + 1));
}

void ViewSession::set_message(std::string text) {
  message_ = std::move(text);
  ++message_count_;
}

Status ViewSession::refuse(Code code, std::string text) {
  set_message(std::move(text));
  return Status::failure(code, message_);
}

void ViewSession::replace_plan(Plan next) {
  undo_.push_back(std::move(plan_));
  if (undo_.size() > kMaxUndo) undo_.erase(undo_.begin());
  plan_ = std::move(next);
  report_ = validate(plan_);
  modified_ = plan_ != base_plan_;
  ++revision_;
  if (selected_ && !object_kind(plan_, *selected_)) selected_.reset();
}

Status ViewSession::apply(std::string_view what, const Edit& edit) {
  Plan next = plan_;
  const Result<EditSummary> made = make_edit(edit, next);
  if (!made) return refuse(made.code(), fmt::format("{}: not done: {}", what, made.message()));
  if (next == plan_) return refuse(Code::edit_refused, fmt::format("{}: nothing changed", what));
  const Report before = report_;
  replace_plan(std::move(next));
  const Report fresh = introduced_errors(before, report_);
  set_message(fresh.ok() ? std::string(what)
                         : fmt::format("{}: introduces {} (in red); Ctrl+Z undoes", what,
                                       error_count(fresh)));
  return Status::success();
}

namespace {
/// The failure of an action on the selection when there is none (the window says nothing).
Status nothing_selected() { return Status::failure(Code::usage_error, "nothing is selected"); }
}  // namespace

Status ViewSession::move_selection(int dx_cells, int dy_cells) {
  pending_cascade_.reset();
  if (!selected_) return nothing_selected();
  const std::string id = *selected_;
  const double cell = plan_.site.cell_size;
  if (object_kind(plan_, id) == std::optional<std::string_view>("door") ||
      object_kind(plan_, id) == std::optional<std::string_view>("window")) {
    const double du = (dx_cells != 0 ? dx_cells : dy_cells) * cell;
    return apply(fmt::format("slid {} by {} m along its wall", id, du),
                 [&](Plan& p) { return slide_opening(p, id, du); });
  }
  const Point2 by{dx_cells * cell, dy_cells * cell};
  return apply(fmt::format("moved {} by {}, {} m", id, by.x, by.y),
               [&](Plan& p) { return move_object(p, id, by); });
}

Status ViewSession::rotate_selection(double degrees) {
  pending_cascade_.reset();
  if (!selected_) return nothing_selected();
  const std::string id = *selected_;
  return apply(fmt::format("turned {} by {} degrees", id, degrees),
               [&](Plan& p) { return rotate_object(p, id, degrees); });
}

Status ViewSession::delete_selection() {
  if (!selected_) return nothing_selected();
  const std::string id = *selected_;
  const std::vector<std::string> hosted = dependent_objects(plan_, id);
  const bool confirmed = pending_cascade_ == id;
  pending_cascade_.reset();
  if (!hosted.empty() && !confirmed) {
    pending_cascade_ = id;
    return refuse(Code::edit_refused,
                  fmt::format("{} holds {}: press Delete again to delete them with it", id,
                              fmt::join(hosted, ", ")));
  }
  return apply(
      fmt::format("deleted {}",
                  hosted.empty() ? id : fmt::format("{} and {}", id, fmt::join(hosted, ", "))),
      [&](Plan& p) { return remove_object(p, id, RemoveOptions{.cascade = confirmed}); });
}

Status ViewSession::undo() {
  pending_cascade_.reset();
  if (undo_.empty()) return refuse(Code::usage_error, "nothing to undo");
  plan_ = std::move(undo_.back());
  undo_.pop_back();
  report_ = validate(plan_);
  modified_ = plan_ != base_plan_;
  ++revision_;
  if (selected_ && !object_kind(plan_, *selected_)) selected_.reset();
  set_message("undone");
  return Status::success();
}

}  // namespace roomcad
