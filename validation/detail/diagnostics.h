// SPDX-License-Identifier: GPL-3.0-or-later
// Building diagnostics: numbers in metres a person can read, and the common shapes of items.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "plan/plan.h"
#include "validation/report.h"

namespace roomcad::detail {

/// @return the exact length a fix must set, as a person reads it: "0.12 m" where that is
///         the value, else rounded to the millimetre with the exact value after it, which the
///         rounded one would not match: "0.120 m (exactly 0.11999988555908203 m)".
[[nodiscard]] std::string exact_metres(double value);

/// @return a length as text: "0.15 m"; 2 decimals, or 3 significant digits below 5 mm so
///         that a micrometre does not print as "0.00 m".
[[nodiscard]] std::string metres(double value);

/// A distance to move or a size to set in a fix, rounded to centimetres so that following
/// the fix really clears the problem: up for "move by at least", down for "make it at most"
/// (a nanometre of slack absorbs the rounding of the measurement itself).
[[nodiscard]] std::string metres_at_least(double value);
[[nodiscard]] std::string metres_at_most(double value);

/// @return "(x, y)" with 2 decimals.
[[nodiscard]] std::string point_text(Point2 p);

/// @return a unit direction as a compass word ("east", "north-east", ...; 8 winds).
[[nodiscard]] std::string direction_text(Point2 unit);

/// @return a box where both corners are the given extremes.
[[nodiscard]] Where box_where(double min_x, double min_y, double max_x, double max_y);

/// @return an error (or warning) with the given parts; `where` is optional.
[[nodiscard]] Diagnostic make_diagnostic(Severity severity, Code code,
                                         std::vector<std::string> objects, std::string message,
                                         std::string fix = {}, std::optional<Where> where = {});

/// @return "wall 'a'", "door 'd1'", ...: how messages name an object.
[[nodiscard]] std::string name_of(const Wall& w);
[[nodiscard]] std::string name_of(const Opening& o);

}  // namespace roomcad::detail
