// SPDX-License-Identifier: GPL-3.0-or-later
// Findings as BCF 2.1 (BIM Collaboration Format, buildingSMART): a zip of one topic per
// finding, each with a viewpoint whose selected components are the IFC GlobalIds that
// `roomcad build -o x.ifc` gives the finding's objects (io/ifc_guid.h), and a camera that
// looks at the finding's place. What `roomcad validate --format bcf -o FILE.bcfzip` writes.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"
#include "validation/report.h"
#include "validation/report_diff.h"

namespace roomcad {

struct BcfInput {
  const Plan* plan = nullptr;                    ///< required
  const Report* report = nullptr;                ///< required
  const ReportComparison* comparison = nullptr;  ///< with a baseline: its fixed items, closed
  std::string plan_file;                         ///< named in each topic's description
  std::string date;                              ///< the topics' CreationDate (xs:dateTime)
  bool snapshots = true;  ///< a PNG render from each viewpoint's camera, `snapshot.png`
};

/// @return the last write time of the file `path` as BCF's CreationDate
///         ("2026-12-07T18:59:32Z"), or 1980-01-01 if it cannot be read: what the archive of
///         a plan file is dated, so that the same file gives the same archive.
[[nodiscard]] std::string file_date_for_bcf(const std::string& path);

/// @return the bytes of the .bcfzip: `bcf.version`, then per finding `GUID/markup.bcf`,
///         `GUID/viewpoint.bcfv` and, with snapshots (and a model that builds),
///         `GUID/snapshot.png`, 320 x 200 pixels from the viewpoint's camera. A topic's GUID is
///         hashed from the finding's identity (item_ids: its code and objects), so an unchanged
///         finding keeps it in every revision; its title is the code and objects, its description
///         the message and fix, its labels the code and severity, its status Open (Closed for the
///         baseline's fixed items). The same input gives the same bytes. O(findings * objects),
///         plus a build and a small render per finding for the snapshots.
[[nodiscard]] Result<std::string> write_bcf_archive(const BcfInput& input);

}  // namespace roomcad
