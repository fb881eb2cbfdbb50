// A report of problems found in a plan: what reading and validation return, printed by the CLI
// as text or as the JSON of ../shared/spec/plan-format.md ("Validation codes").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "modeling/plan.h"

namespace roomcad {

enum class Severity { error, warning };

/// A point or a box in metres that locates a problem (`where` in the JSON).
struct Where {
  Point2 min;
  std::optional<Point2> max;  ///< set for a box, empty for a point
  friend bool operator==(const Where&, const Where&) = default;
};

/// Where a problem sits in the plan file (set by the reader; line and column count from 1).
struct SourceLocation {
  std::string file;
  std::string pointer;  ///< JSON pointer, e.g. "/walls/3/thickness"
  std::size_t line = 0;
  std::size_t column = 0;
  friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

/// One problem: `code` is one of the spec's codes (parse_error, wall_overlap, ...).
struct Diagnostic {
  Severity severity = Severity::error;
  std::string code;
  std::vector<std::string> objects;  ///< ids involved, possibly empty
  std::string message;               ///< one sentence a person can act on
  std::string fix;                   ///< a concrete change that removes it (may be empty)
  std::optional<Where> where;
  std::optional<SourceLocation> source;
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
