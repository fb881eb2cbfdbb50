// SPDX-License-Identifier: GPL-3.0-or-later
// What every edit command (add, rm, move, rotate, scale, set) does around its edit: read the
// plan, apply the edit to a copy, validate, refuse an edit that INTRODUCES errors (unless
// --force), show the change (--dry-run) or write the file atomically.
//
// "Introduces" is counted per (code, ids involved): the edit is refused when the edited plan
// has more errors of some code about some set of objects than the original had. So a plan that
// already has errors can still be edited (to repair it, or elsewhere), and the same overlap,
// reworded because a wall moved, is not new. A refused edit leaves the file byte for byte as
// it was; so does an edit that changes nothing.
//
// The plan's lock (io/plan_lock.h) is held from reading the plan to renaming the new file over
// it, so concurrent edits of one plan (other commands, `roomcad view` saving) happen one after
// the other and none is lost; an edit waits up to --wait seconds for the lock.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "plan/plan.h"
#include "plan/plan_edit.h"

namespace roomcad::cli {

/// The flags every edit command takes.
struct EditFlags {
  bool force = false;         ///< write even when the edit introduces errors
  bool dry_run = false;       ///< print what would change, write nothing (takes no lock)
  double wait_seconds = 0.0;  ///< how long to wait for another editor's lock (--wait)
  bool verbose = false;       ///< list the plan's findings as read (else one line counts them)
};

/// Registers --force, --dry-run, --wait and --verbose on an edit subcommand.
void add_edit_flags(CLI::App& command, EditFlags& flags);

/// An edit of an in-memory plan: returns what it changed, or the Error why not (set_field and
/// add_object return it; the typed edits of plan/plan_edit.h throw it as PreconditionError
/// for their preconditions). Code::edit_refused refuses it on the plan's grounds (a wall that
/// still holds openings: run_edit prints "roomcad <command>: refused: <what>" and returns 1,
/// the file untouched); any other code means it cannot be made (a bad argument: exit 2).
using Edit = std::function<Result<EditSummary>(Plan&)>;

/// Runs one edit on the plan file `path` and reports on stdout/stderr.
/// @param[in] command  the subcommand's name, for messages ("move")
/// @return 0 done (or dry run shown, or nothing to change), 1 refused because the result has
///         new errors or the plan could not be read as a plan, 2 usage or I/O error, or the
///         lock held by another editor for longer than --wait.
[[nodiscard]] int run_edit(std::string_view command, const std::string& path,
                           const EditFlags& flags, const Edit& edit);

/// @return `text` as a point x,y, or a usage_error naming `option` and the text.
[[nodiscard]] Result<Point2> point_option(std::string_view option, const std::string& text);

/// @return `text` as a finite number, or a usage_error naming `option` and the text.
[[nodiscard]] Result<double> number_option(std::string_view option, const std::string& text);

}  // namespace roomcad::cli
