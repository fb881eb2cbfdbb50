// SPDX-License-Identifier: GPL-3.0-or-later
// Shared helpers of the io tests: the spec's example plan and error expectations.
#pragma once

#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "io/plan_json.h"
#include "support/plan_reading.h"

namespace roomcad::test {

/// The example document of docs/plan-format.md, as written there.
inline constexpr std::string_view kSpecExample = R"({
  "format": "roomcad-plan",
  "version": 1,
  "units": "m",
  "site":   { "origin": [0, 0], "cells": [12, 8], "cell_size": 1.0, "max_height": 6.0,
              "tolerance": 1e-6, "floor_color": "#c8c8c8" },
  "walls": [
    { "id": "south", "from": [1, 1], "to": [11, 1], "thickness": 0.25, "height": 2.8,
      "base": 0.0, "color": "#e8e2d0" }
  ],
  "openings": [
    { "id": "entry", "type": "door",   "wall": "south", "offset": 1.5, "width": 0.9,
      "height": 2.1, "sill": 0.0, "hinge": "left", "swing": "in" },
    { "id": "win1",  "type": "window", "wall": "south", "offset": 5.0, "width": 1.4,
      "height": 1.3, "sill": 0.9 }
  ],
  "lights":  [ { "id": "sun", "type": "directional", "direction": [-0.4, 0.5, -1.0],
                 "intensity": 1.0, "ambient": 0.25 } ],
  "cameras": [ { "id": "view", "projection": "perspective", "eye": [16, -9, 10],
                 "target": [6, 4, 1], "up": [0, 0, 1], "fov_deg": 50 },
               { "id": "plan", "projection": "orthographic", "eye": [6, 4, 20],
                 "target": [6, 4, 0], "up": [0, 1, 0], "view_height": 10 } ]
}
)";

/// The canonical text of the spec's example.
inline constexpr std::string_view kSpecCanonical = R"({
  "format": "roomcad-plan",
  "version": 1,
  "units": "m",
  "site": {"origin": [0, 0], "cells": [12, 8], "cell_size": 1, "max_height": 6, "tolerance": 1e-06, "floor_color": "#c8c8c8"},
  "walls": [
    {"id": "south", "from": [1, 1], "to": [11, 1], "thickness": 0.25, "height": 2.8, "base": 0, "color": "#e8e2d0"}
  ],
  "openings": [
    {"id": "entry", "type": "door", "wall": "south", "offset": 1.5, "width": 0.9, "height": 2.1, "sill": 0, "hinge": "left", "swing": "in"},
    {"id": "win1", "type": "window", "wall": "south", "offset": 5, "width": 1.4, "height": 1.3, "sill": 0.9, "hinge": "left", "swing": "in"}
  ],
  "lights": [
    {"id": "sun", "type": "directional", "direction": [-0.4, 0.5, -1], "intensity": 1, "ambient": 0.25}
  ],
  "cameras": [
    {"id": "view", "projection": "perspective", "eye": [16, -9, 10], "target": [6, 4, 1], "up": [0, 0, 1], "fov_deg": 50, "view_height": 10},
    {"id": "plan", "projection": "orthographic", "eye": [6, 4, 20], "target": [6, 4, 0], "up": [0, 1, 0], "fov_deg": 50, "view_height": 10}
  ]
}
)";

/// Reads `text`, which must have no error, and returns the plan.
inline Plan read_ok(std::string_view text) {
  PlanReading r = read_plan(text, "plan.json");
  EXPECT_TRUE(r.report.ok()) << (r.report.items.empty() ? "" : r.report.items[0].message);
  EXPECT_TRUE(r.plan.has_value());
  return r.plan.value_or(Plan{});
}

/// What one diagnostic must say.
struct Expected {
  Code code = Code::parse_error;
  std::string pointer;
  std::size_t line = 0;    ///< 0: not checked
  std::size_t column = 0;  ///< 0: not checked
  std::string text;        ///< a substring of the message
};

/// Checks that reading `text` fails with exactly one problem, as `e` says.
inline void expect_one_error(std::string_view text, const Expected& e) {
  SCOPED_TRACE(std::string(text));
  const PlanReading r = read_plan(text, "plan.json");
  EXPECT_FALSE(r.plan.has_value());
  ASSERT_EQ(r.report.items.size(), 1u)
      << r.report.items[0].message << " / " << r.report.items.back().message;
  const Diagnostic& d = r.report.items[0];
  EXPECT_EQ(d.severity, Severity::error);
  EXPECT_EQ(d.code, e.code) << d.message;
  ASSERT_TRUE(d.location.has_value());
  EXPECT_EQ(d.location->file, "plan.json");
  EXPECT_EQ(d.location->pointer, e.pointer) << d.message;
  if (e.line) {
    EXPECT_EQ(d.location->line, e.line) << d.message;
  }
  if (e.column) {
    EXPECT_EQ(d.location->column, e.column) << d.message;
  }
  EXPECT_NE(d.message.find(e.text), std::string::npos) << d.message;
  // The message names the file, the position and the pointer.
  const std::string prefix = "plan.json:" + std::to_string(d.location->line) + ':' +
                             std::to_string(d.location->column) + ": ";
  EXPECT_EQ(d.message.rfind(prefix, 0), 0u) << d.message;
  if (!e.pointer.empty()) {
    EXPECT_NE(d.message.find(e.pointer + ": "), std::string::npos) << d.message;
  }
}

}  // namespace roomcad::test
