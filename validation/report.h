// A report of problems found in a plan: what reading and validation return, printed by the CLI
// as text or as the JSON of docs/plan-format.md ("Validation codes").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "modeling/plan.h"

namespace roomcad {

enum class Severity { error, warning };

/// A point or a box in metres that locates a problem (`where` in the JSON).
struct Where {
  Point2 min;
  std::optional<Point2> max;  ///< set for a box, empty for a point
  friend bool operator==(const Where&, const Where&) = default;
};

/// One problem: its code (core/code.h: the format's codes, parse_error, wall_overlap, ...).
struct Diagnostic {
  Severity severity = Severity::error;
  Code code = Code::invalid_value;
  std::vector<std::string> objects;  ///< ids involved, possibly empty
  std::string message;               ///< one sentence a person can act on
  std::string fix;                   ///< a concrete change that removes it (may be empty)
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
