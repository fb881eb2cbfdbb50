// SPDX-License-Identifier: GPL-3.0-or-later
// SVG text generation: attributes, number formatting and escaping.
#include "io/svg_writer.h"

#include <fmt/format.h>

#include <cmath>

#include "io/atomic_write.h"

namespace roomcad {
namespace {

std::string format_point(Point2 p) {
  return fmt::format("{},{}", format_svg_number(p.x), format_svg_number(p.y));
}

void append_attribute(std::string& out, std::string_view name, std::string_view value) {
  if (value.empty()) return;
  out += fmt::format(" {}=\"{}\"", name, escape_xml(value));
}

std::string style_attributes(const SvgStyle& style) {
  std::string out;
  append_attribute(out, "class", style.css_class);
  append_attribute(out, "stroke", style.stroke);
  if (style.stroke_width > 0.0) {
    append_attribute(out, "stroke-width", format_svg_number(style.stroke_width));
  }
  append_attribute(out, "fill", style.fill);
  if (!style.dashes.empty()) {
    std::string dashes;
    for (const double d : style.dashes) {
      if (!dashes.empty()) dashes += ' ';
      dashes += format_svg_number(d);
    }
    append_attribute(out, "stroke-dasharray", dashes);
  }
  append_attribute(out, "stroke-linecap", style.linecap);
  return out;
}

}  // namespace

std::string format_svg_number(double x) {
  std::string text = fmt::format("{:.3f}", x);
  while (text.back() == '0') text.pop_back();
  if (text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

SvgPath& SvgPath::move_to(Point2 p) {
  data_ += data_.empty() ? "M" : " M";
  data_ += format_point(p);
  return *this;
}

SvgPath& SvgPath::line_to(Point2 p) {
  data_ += " L";
  data_ += format_point(p);
  return *this;
}

SvgPath& SvgPath::arc_to(double rx, double ry, double rotation_deg, bool large_arc, bool sweep,
                         Point2 p) {
  data_ += fmt::format(" A{},{} {} {} {} {}", format_svg_number(rx), format_svg_number(ry),
                       format_svg_number(rotation_deg), large_arc ? 1 : 0, sweep ? 1 : 0,
                       format_point(p));
  return *this;
}

SvgPath& SvgPath::close() {
  data_ += " Z";
  return *this;
}

SvgDocument::SvgDocument(double width_mm, double height_mm)
    : width_(width_mm), height_(height_mm) {}

void SvgDocument::set_title(std::string_view title) { title_ = title; }

void SvgDocument::begin_group(std::string_view id, std::string_view css_class,
                              const SvgStyle& style) {
  SvgStyle with_class = style;
  if (!css_class.empty()) with_class.css_class = css_class;
  std::string attributes;
  append_attribute(attributes, "id", id);
  body_ += fmt::format("<g{}{}>\n", attributes, style_attributes(with_class));
  ++open_groups_;
}

void SvgDocument::end_group() {
  if (open_groups_ == 0) return;
  body_ += "</g>\n";
  --open_groups_;
}

void SvgDocument::add_line(Point2 a, Point2 b, const SvgStyle& style) {
  body_ += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"{}/>\n",
                       format_svg_number(a.x), format_svg_number(a.y), format_svg_number(b.x),
                       format_svg_number(b.y), style_attributes(style));
}

void SvgDocument::add_points_element(std::string_view tag, std::span<const Point2> points,
                                     const SvgStyle& style) {
  std::string list;
  for (const Point2& p : points) {
    if (!list.empty()) list += ' ';
    list += format_point(p);
  }
  body_ += fmt::format("<{} points=\"{}\"{}/>\n", tag, list, style_attributes(style));
}

void SvgDocument::add_polyline(std::span<const Point2> points, const SvgStyle& style) {
  SvgStyle open = style;
  if (open.fill.empty()) open.fill = "none";  // SVG fills polylines black by default
  add_points_element("polyline", points, open);
}

void SvgDocument::add_polygon(std::span<const Point2> points, const SvgStyle& style) {
  add_points_element("polygon", points, style);
}

void SvgDocument::add_rect(Point2 corner, double width, double height, const SvgStyle& style) {
  body_ +=
      fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"{}/>\n",
                  format_svg_number(corner.x), format_svg_number(corner.y),
                  format_svg_number(width), format_svg_number(height), style_attributes(style));
}

void SvgDocument::add_circle(Point2 centre, double radius, const SvgStyle& style) {
  body_ +=
      fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"{}/>\n", format_svg_number(centre.x),
                  format_svg_number(centre.y), format_svg_number(radius), style_attributes(style));
}

void SvgDocument::add_path(const SvgPath& path, const SvgStyle& style) {
  SvgStyle open = style;
  if (open.fill.empty()) open.fill = "none";
  body_ += fmt::format("<path d=\"{}\"{}/>\n", path.data(), style_attributes(open));
}

void SvgDocument::add_text(Point2 at, std::string_view text, const SvgTextStyle& style) {
  std::string attributes;
  append_attribute(attributes, "class", style.css_class);
  append_attribute(attributes, "font-size", format_svg_number(style.size));
  append_attribute(attributes, "font-family", style.family);
  append_attribute(attributes, "text-anchor", style.anchor);
  append_attribute(attributes, "fill", style.fill);
  if (style.rotate_deg != 0.0) {
    append_attribute(attributes, "transform",
                     fmt::format("rotate({} {} {})", format_svg_number(style.rotate_deg),
                                 format_svg_number(at.x), format_svg_number(at.y)));
  }
  body_ += fmt::format("<text x=\"{}\" y=\"{}\"{}>{}</text>\n", format_svg_number(at.x),
                       format_svg_number(at.y), attributes, escape_xml(text));
}

std::string SvgDocument::to_string() const {
  const std::string w = format_svg_number(width_);
  const std::string h = format_svg_number(height_);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}mm\" height=\"{1}mm\" "
      "viewBox=\"0 0 {0} {1}\">\n",
      w, h);
  if (!title_.empty()) out += fmt::format("<title>{}</title>\n", escape_xml(title_));
  out += body_;
  for (int i = 0; i < open_groups_; ++i) out += "</g>\n";
  out += "</svg>\n";
  return out;
}

Status write_svg(const SvgDocument& document, const std::filesystem::path& path) {
  return write_file_atomically(path, document.to_string());
}

}  // namespace roomcad
