// SPDX-License-Identifier: GPL-3.0-or-later
// The report page of `roomcad report`: one self-contained HTML file (inline SVG, CSS and a
// small script of its own; nothing fetched) with a summary of a plan's findings, a floor plan
// per level whose walls, openings, slabs and rooms carry `data-id`, and the findings list:
// selecting a finding marks its objects `selected` and zooms the plans to its place.
#pragma once

#include <string>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"
#include "validation/report_diff.h"

namespace roomcad {

/// An edit the page lists (`roomcad report --repair`): the objects it touches and what it does.
struct ReportPageEdit {
  std::vector<std::string> objects;  ///< the edited object first, then those of what it clears
  std::string text;                  ///< "trim wall 'a': clears 2 errors, moves the solid 0 mm"
};

/// What the page shows. Pointers are not owned and may be null where optional.
struct ReportPageInput {
  std::string title;                                      ///< the plan file, as given
  const Plan* plan = nullptr;                             ///< required
  const Report* report = nullptr;                         ///< required
  const std::vector<std::string>* item_levels = nullptr;  ///< item_levels(report, plan)
  const ReportComparison* comparison = nullptr;           ///< with --baseline
  std::string baseline_file;
  std::string level;        ///< draw and list only this level's objects and findings
  std::string picture_png;  ///< the bytes of a render of the model; empty: none
  /// With `--repair`: the edits `roomcad repair` would make, each selectable like a finding.
  std::vector<ReportPageEdit> edits{};
  bool repaired = false;  ///< whether repair ran (a section even when it makes no edit)
};

/// @return the page's picture: the model rendered from the plan's first camera (or the
///         default view) at 960 x 540, as PNG bytes; empty, with a note on stderr, where the
///         model cannot be built. O(build + render).
[[nodiscard]] std::string render_picture_png(const Plan& plan);

/// @return the page. Deterministic: the same input gives the same bytes. O(n log n) for the
///         plan's objects and the findings (rooms are found level by level).
/// @pre input.plan and input.report are set; item_levels, if set, has one entry per item.
[[nodiscard]] std::string make_report_page(const ReportPageInput& input);

}  // namespace roomcad
