// SPDX-License-Identifier: GPL-3.0-or-later
// A small SVG document builder for drawings (surfaces, floor plans, elevations). User units are
// millimetres on paper: the document is width x height mm with viewBox "0 0 width height".
// Output is deterministic: numbers are written with at most three decimals (a micrometre on
// paper), trailing zeros dropped, elements in the order they were added.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

/// Presentation attributes; empty or non-positive members are left out of the element.
struct SvgStyle {
  std::string stroke{};          ///< a colour, e.g. "#000" or "none"
  double stroke_width = 0.0;     ///< mm
  std::string fill{};            ///< a colour or "none"
  std::vector<double> dashes{};  ///< stroke-dasharray in mm
  std::string css_class{};
  std::string linecap{};  ///< "butt", "round" or "square"
};

/// Text placement and look.
struct SvgTextStyle {
  double size = 3.5;     ///< font size, mm
  std::string anchor{};  ///< "start", "middle" or "end"; empty = SVG default (start)
  std::string fill = "#000";
  std::string family = "sans-serif";
  double rotate_deg = 0.0;  ///< clockwise about the anchor point, as SVG rotate()
  std::string css_class{};
};

/// Path data built from commands (absolute coordinates, mm).
class SvgPath {
 public:
  SvgPath& move_to(Point2 p);
  SvgPath& line_to(Point2 p);
  /// An elliptical arc to `p` (SVG "A"): radii, x-axis rotation in degrees, flags.
  SvgPath& arc_to(double rx, double ry, double rotation_deg, bool large_arc, bool sweep, Point2 p);
  SvgPath& close();
  [[nodiscard]] const std::string& data() const { return data_; }

 private:
  std::string data_;
};

/// An SVG document under construction. Groups nest; the text is produced by to_string().
class SvgDocument {
 public:
  /// @param width_mm, height_mm  paper size, > 0
  SvgDocument(double width_mm, double height_mm);

  /// Adds a <title> (shown by viewers, read by screen readers) as the first child.
  void set_title(std::string_view title);
  /// Opens a <g>; `id` and `css_class` may be empty. Attributes of `style` are inherited.
  void begin_group(std::string_view id, std::string_view css_class = {},
                   const SvgStyle& style = {});
  /// Closes the innermost open group. @pre a group is open.
  void end_group();

  void add_line(Point2 a, Point2 b, const SvgStyle& style = {});
  /// @param points  at least two
  void add_polyline(std::span<const Point2> points, const SvgStyle& style = {});
  void add_polygon(std::span<const Point2> points, const SvgStyle& style = {});
  void add_rect(Point2 corner, double width, double height, const SvgStyle& style = {});
  void add_circle(Point2 centre, double radius, const SvgStyle& style = {});
  void add_path(const SvgPath& path, const SvgStyle& style = {});
  /// Adds escaped text whose anchor point is `at` (the baseline).
  void add_text(Point2 at, std::string_view text, const SvgTextStyle& style = {});

  /// @return the document text (open groups are closed). O(size).
  [[nodiscard]] std::string to_string() const;

 private:
  void add_points_element(std::string_view tag, std::span<const Point2> points,
                          const SvgStyle& style);
  double width_;
  double height_;
  std::string title_;
  std::string body_;
  int open_groups_ = 0;
};

/// @return x with at most three decimals, no trailing zeros, "-0" written as "0".
/// @pre std::isfinite(x)
[[nodiscard]] std::string format_svg_number(double x);

/// @return text with & < > " ' escaped for XML.
[[nodiscard]] std::string escape_xml(std::string_view text);

/// Writes the document atomically (io/atomic_write.h). Errors name the file and the reason.
Status write_svg(const SvgDocument& document, const std::filesystem::path& path);

}  // namespace roomcad
