// SPDX-License-Identifier: GPL-3.0-or-later
// A report of problems found in a plan: what reading and validation return, printed by the CLI
// as text or as the JSON of docs/plan-format.md ("Validation codes").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

enum class Severity { error, warning };

/// A point or a box in metres that locates a problem (`where` in the JSON).
struct Where {
  Point2 min;
  std::optional<Point2> max;  ///< set for a box, empty for a point
  friend bool operator==(const Where&, const Where&) = default;
};

/// One edit of a fix, as the edit commands make it (plan/plan_edit.h): set fields of an
/// object (`roomcad set PLAN ID key=value...`), add an opening (`roomcad add PLAN door|window
/// --wall W ...`), or remove an object (`roomcad rm PLAN ID [--cascade]`).
struct FixEdit {
  enum class Op : std::uint8_t { set, add, remove };
  Op op = Op::set;
  std::string id;  ///< the object set or removed; for add, the new opening's id
  /// set: key, value pairs as set_field reads them; add: the new opening's fields, "type" first.
  std::vector<std::pair<std::string, std::string>> fields;
  bool cascade = false;  ///< remove: a wall's openings go with it
  friend bool operator==(const FixEdit&, const FixEdit&) = default;
};

/// One problem: its code (core/code.h: the format's codes, parse_error, wall_overlap, ...).
struct Diagnostic {
  Severity severity = Severity::error;
  Code code = Code::invalid_value;
  std::vector<std::string> objects;  ///< ids involved, possibly empty
  std::string message;               ///< one sentence a person can act on
  std::string fix;                   ///< a concrete change that removes it (may be empty)
  std::vector<FixEdit> edits;        ///< the fix as edits, when it is one (rule findings)
  std::optional<Where> where;
  std::optional<Location> location;  ///< in the plan file, set by the reader
  friend bool operator==(const Diagnostic&, const Diagnostic&) = default;
};

struct Report {
  std::vector<Diagnostic> items;

  [[nodiscard]] bool ok() const;  ///< no item is an error
  [[nodiscard]] std::size_t error_count() const;
  [[nodiscard]] std::size_t warning_count() const;
  void add(Diagnostic d) { items.push_back(std::move(d)); }
  void append(const Report& other);
};

}  // namespace roomcad
