#include "io/plan_json.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <string>

#include "io/atomic_write.h"
#include "io/detail/json_text.h"
#include "io/detail/plan_reader.h"
#include "io/detail/positioned_json.h"
#include "io/text_file.h"

namespace roomcad {
namespace {

using io_detail::append_number;
using io_detail::append_string;
using KnownKeys = std::initializer_list<std::string_view>;

/// The unknown fields to write, sorted by key. Keys the format knows, or repeated ones, are
/// left out: writing them would make a duplicate key.
std::vector<const ExtraField*> writable_extras(const ExtraFields& extra, KnownKeys known) {
  std::vector<const ExtraField*> sorted;
  for (const ExtraField& e : extra)
    if (std::find(known.begin(), known.end(), e.key) == known.end()) sorted.push_back(&e);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const ExtraField* a, const ExtraField* b) { return a->key < b->key; });
  sorted.erase(std::unique(sorted.begin(), sorted.end(),
                           [](const ExtraField* a, const ExtraField* b) { return a->key == b->key; }),
               sorted.end());
  return sorted;
}

/// Writes the members of one line of canonical JSON: `"key": value, ...`.
class LineWriter {
 public:
  explicit LineWriter(std::string& out) : out_(out) {}
  void key(std::string_view k) {
    if (!first_) out_ += ", ";
    first_ = false;
    append_string(out_, k);
    out_ += ": ";
  }
  void number(std::string_view k, double x) { key(k), append_number(out_, x); }
  void integer(std::string_view k, std::int64_t n) { key(k), out_ += std::to_string(n); }
  void string(std::string_view k, std::string_view s) { key(k), append_string(out_, s); }
  void point(std::string_view k, Point2 p) {
    key(k), out_ += '[', append_number(out_, p.x), out_ += ", ", append_number(out_, p.y), out_ += ']';
  }
  void vec(std::string_view k, Vec3 v) {
    key(k), out_ += '[', append_number(out_, v.x), out_ += ", ", append_number(out_, v.y);
    out_ += ", ", append_number(out_, v.z), out_ += ']';
  }
  /// Unknown fields, after the known ones.
  void extras(const ExtraFields& extra, KnownKeys known) {
    for (const ExtraField* e : writable_extras(extra, known)) key(e->key), out_ += e->json;
  }

 private:
  std::string& out_;
  bool first_ = true;
};

void write_site(std::string& out, const Site& s) {
  out += '{';
  LineWriter w(out);
  w.point("origin", s.origin);
  w.key("cells");
  out += '[' + std::to_string(s.cells[0]) + ", " + std::to_string(s.cells[1]) + ']';
  w.number("cell_size", s.cell_size);
  w.number("max_height", s.max_height);
  w.number("tolerance", s.tolerance);
  w.string("floor_color", to_string(s.floor_color));
  w.extras(s.extra, {"origin", "cells", "cell_size", "max_height", "tolerance", "floor_color"});
  out += '}';
}

void write_one(std::string& out, const Wall& x) {
  LineWriter w(out);
  w.string("id", x.id);
  w.point("from", x.from);
  w.point("to", x.to);
  w.number("thickness", x.thickness);
  w.number("height", x.height);
  w.number("base", x.base);
  w.string("color", to_string(x.color));
  w.extras(x.extra, {"id", "from", "to", "thickness", "height", "base", "color"});
}

void write_one(std::string& out, const Opening& x) {
  LineWriter w(out);
  w.string("id", x.id);
  w.string("type", to_string(x.type));
  w.string("wall", x.wall);
  w.number("offset", x.offset);
  w.number("width", x.width);
  w.number("height", x.height);
  w.number("sill", x.sill);
  w.string("hinge", to_string(x.hinge));
  w.string("swing", to_string(x.swing));
  w.extras(x.extra,
           {"id", "type", "wall", "offset", "width", "height", "sill", "hinge", "swing"});
}

void write_one(std::string& out, const Light& x) {
  LineWriter w(out);
  w.string("id", x.id);
  w.string("type", to_string(x.type));
  w.vec("direction", x.direction);
  w.number("intensity", x.intensity);
  w.number("ambient", x.ambient);
  w.extras(x.extra, {"id", "type", "direction", "intensity", "ambient"});
}

void write_one(std::string& out, const Camera& x) {
  LineWriter w(out);
  w.string("id", x.id);
  w.string("projection", to_string(x.projection));
  w.vec("eye", x.eye);
  w.vec("target", x.target);
  w.vec("up", x.up);
  w.number("fov_deg", x.fov_deg);
  w.number("view_height", x.view_height);
  w.extras(x.extra, {"id", "projection", "eye", "target", "up", "fov_deg", "view_height"});
}

template <class T>
void write_array(std::string& out, std::string_view key, const std::vector<T>& items) {
  out += "  ";
  append_string(out, key);
  if (items.empty()) {
    out += ": []";
    return;
  }
  out += ": [\n";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += "    {";
    write_one(out, items[i]);
    out += i + 1 < items.size() ? "},\n" : "}\n";
  }
  out += "  ]";
}

/// @return the first number of the plan that JSON cannot hold, as "walls/2/thickness", or "".
std::string first_non_finite(const Plan& plan) {
  std::string where;
  auto check = [&](std::string_view path, std::initializer_list<double> values) {
    for (double v : values)
      if (where.empty() && !std::isfinite(v)) where = path;
  };
  const Site& s = plan.site;
  check("site", {s.origin.x, s.origin.y, s.cell_size, s.max_height, s.tolerance});
  for (const Wall& w : plan.walls)
    check("wall \"" + w.id + '"', {w.from.x, w.from.y, w.to.x, w.to.y, w.thickness, w.height, w.base});
  for (const Opening& o : plan.openings)
    check("opening \"" + o.id + '"', {o.offset, o.width, o.height, o.sill});
  for (const Light& l : plan.lights)
    check("light \"" + l.id + '"',
          {l.direction.x, l.direction.y, l.direction.z, l.intensity, l.ambient});
  for (const Camera& c : plan.cameras)
    check("camera \"" + c.id + '"', {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y,
                                     c.target.z, c.up.x, c.up.y, c.up.z, c.fov_deg, c.view_height});
  return where;
}

}  // namespace

Result<Plan> read_plan_text(std::string_view text, std::string_view file, Report* report) {
  Report found;
  const io_detail::PositionedJson doc = io_detail::parse_positioned_json(text);
  Plan plan;
  if (doc.error) {
    const io_detail::LineColumn at = io_detail::line_column_at(text, doc.error->offset);
    Diagnostic d;
    d.code = doc.error->not_finite ? Code::invalid_value : Code::parse_error;
    d.message = std::string(file) + ':' + std::to_string(at.line) + ':' +
                std::to_string(at.column) + ": " +
                (doc.error->pointer.empty() ? "" : doc.error->pointer + ": ") + doc.error->message;
    if (doc.error->not_finite) d.fix = "write a finite number (metres, or the file's units)";
    d.location = Location{std::string(file), doc.error->pointer, at.line, at.column};
    found.add(std::move(d));
  } else {
    plan = io_detail::read_plan_document(doc, text, file, found);
  }
  if (report) report->append(found);
  for (const Diagnostic& d : found.items)
    if (d.severity == Severity::error) return Error{d.code, d.message, d.location};
  return plan;
}

Result<Plan> read_plan_file(const std::filesystem::path& path, Report* report) {
  const Result<std::string> text = read_text_file(path);
  if (!text) return text.error();
  return read_plan_text(text.value(), path.string(), report);
}

std::string write_plan_text(const Plan& plan) {
  std::string out = "{\n  \"format\": \"roomcad-plan\",\n  \"version\": 1,\n  \"units\": \"m\",\n";
  out += "  \"site\": ";
  write_site(out, plan.site);
  out += ",\n";
  write_array(out, "walls", plan.walls);
  out += ",\n";
  write_array(out, "openings", plan.openings);
  out += ",\n";
  write_array(out, "lights", plan.lights);
  out += ",\n";
  write_array(out, "cameras", plan.cameras);
  // Top-level unknown fields: one per line after the known ones.
  for (const ExtraField* e : writable_extras(plan.extra, {"format", "version", "units", "site",
                                                          "walls", "openings", "lights", "cameras"})) {
    out += ",\n  ";
    append_string(out, e->key);
    out += ": " + e->json;
  }
  out += "\n}\n";
  return out;
}

Status write_plan_file(const Plan& plan, const std::filesystem::path& path) {
  if (const std::string where = first_non_finite(plan); !where.empty()) {
    return Status::failure(Code::invalid_value, "cannot write " + path.string() + ": " + where +
                           " has a number that is not finite (JSON cannot hold it)");
  }
  return write_file_atomically(path, write_plan_text(plan));
}

}  // namespace roomcad
