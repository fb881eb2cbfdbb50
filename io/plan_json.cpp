// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/plan_json.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/atomic_write.h"
#include "io/detail/json_text.h"
#include "io/detail/plan_reader.h"
#include "io/text_file.h"
#include "io/utf8_text.h"
#include "plan/plan_fields.h"
#include "plan/plan_objects.h"

namespace roomcad {
namespace {

using io_detail::append_number;
using io_detail::append_string;

/// The unknown fields to write, sorted by key. A key written already as a field, or repeated,
/// is left out: writing it would make a duplicate key.
std::vector<const ExtraField*> writable_extras(const ExtraFields& extra,
                                               const std::vector<std::string_view>& written) {
  std::vector<const ExtraField*> sorted;
  for (const ExtraField& e : extra)
    if (std::find(written.begin(), written.end(), e.key) == written.end()) sorted.push_back(&e);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const ExtraField* a, const ExtraField* b) { return a->key < b->key; });
  sorted.erase(
      std::unique(sorted.begin(), sorted.end(),
                  [](const ExtraField* a, const ExtraField* b) { return a->key == b->key; }),
      sorted.end());
  return sorted;
}

/// Writes one object of canonical JSON on one line: `"key": value, ...`, the fields of its
/// table in order (a version-2 field only when present), then its unknown fields by key.
class LineWriter {
 public:
  explicit LineWriter(std::string& out) : out_(out) {}

  template <class Object>
  void object(const Object& o) {
    std::vector<std::string_view> written;
    for (const Field<Object>& f : fields_of<Object>()) {
      if (!is_present(o, f)) continue;
      key(f.name);
      written.push_back(f.name);
      std::visit([&](auto member) { value(o.*member); }, f.member);
    }
    extras(o.extra, written);
  }

  /// Unknown fields, after the known ones (writable_extras).
  void extras(const ExtraFields& extra, const std::vector<std::string_view>& written) {
    for (const ExtraField* e : writable_extras(extra, written)) key(e->key), out_ += e->json;
  }

 private:
  void key(std::string_view k) {
    if (!first_) out_ += ", ";
    first_ = false;
    append_string(out_, k);
    out_ += ": ";
  }
  void value(double x) { append_number(out_, x); }
  void value(const std::optional<double>& x) { append_number(out_, x.value_or(0.0)); }
  void value(const std::string& s) { append_string(out_, s); }
  void value(Color c) { append_string(out_, to_string(c)); }
  void value(Point2 p) {
    out_ += '[', append_number(out_, p.x), out_ += ", ", append_number(out_, p.y), out_ += ']';
  }
  void value(Vec3 v) {
    out_ += '[', append_number(out_, v.x), out_ += ", ", append_number(out_, v.y);
    out_ += ", ", append_number(out_, v.z), out_ += ']';
  }
  void value(const std::array<std::int64_t, 2>& cells) {
    out_ += '[' + std::to_string(cells[0]) + ", " + std::to_string(cells[1]) + ']';
  }
  void value(const Polygon& polygon) {
    out_ += '[';
    for (std::size_t i = 0; i < polygon.size(); ++i) out_ += i ? ", " : "", value(polygon[i]);
    out_ += ']';
  }
  void value(const std::optional<GeoLocation>& location) {
    out_ += '{';
    LineWriter(out_).object(location.value_or(GeoLocation{}));
    out_ += '}';
  }
  void value(const std::vector<Polygon>& polygons) {
    out_ += '[';
    for (std::size_t i = 0; i < polygons.size(); ++i) out_ += i ? ", " : "", value(polygons[i]);
    out_ += ']';
  }
  template <class E>
  requires std::is_enum_v<E>
  void value(E e) { append_string(out_, to_string(e)); }

  std::string& out_;
  bool first_ = true;
};

template <class Object>
void write_array(std::string& out, std::string_view key, const std::vector<Object>& items) {
  out += ",\n  ";
  append_string(out, key);
  if (items.empty()) {
    out += ": []";
    return;
  }
  out += ": [\n";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += "    {";
    LineWriter(out).object(items[i]);
    out += i + 1 < items.size() ? "},\n" : "}\n";
  }
  out += "  ]";
}

bool non_finite(double x) { return !std::isfinite(x); }
bool non_finite(Point2 p) { return non_finite(p.x) || non_finite(p.y); }
bool non_finite(const Polygon& polygon) {
  return std::any_of(polygon.begin(), polygon.end(), [](Point2 p) { return non_finite(p); });
}

/// @return why JSON cannot hold the value `v` of a field, or "".
template <class T>
std::string_view unwritable(const T& v) {
  constexpr std::string_view not_finite = "holds a number that is not finite";
  if constexpr (std::is_same_v<T, std::string>)
    return first_ill_formed_utf8(v) ? "holds text that is not UTF-8" : "";
  else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, Point2> ||
                     std::is_same_v<T, Polygon>)
    return non_finite(v) ? not_finite : "";
  else if constexpr (std::is_same_v<T, std::optional<double>>)
    return v && non_finite(*v) ? not_finite : "";
  else if constexpr (std::is_same_v<T, Vec3>)
    return non_finite(v.x) || non_finite(v.y) || non_finite(v.z) ? not_finite : "";
  else if constexpr (std::is_same_v<T, std::optional<GeoLocation>>)
    return v && (non_finite(v->latitude) || non_finite(v->longitude) || non_finite(v->utc_offset))
               ? not_finite
               : "";
  else if constexpr (std::is_same_v<T, std::vector<Polygon>>)
    return std::any_of(v.begin(), v.end(), [](const Polygon& p) { return non_finite(p); })
               ? not_finite
               : "";
  else return "";
}

/// Sets `where` to "<object> field '<name>' <why>" for the first field of `o` JSON cannot hold
/// (an unknown field's name included), unless `where` names one already.
template <class Object>
void find_unwritable(const Object& o, std::string_view object, std::string& where) {
  for (const Field<Object>& f : fields_of<Object>()) {
    if (!where.empty()) return;
    const std::string_view why =
        std::visit([&](auto member) { return unwritable(o.*member); }, f.member);
    if (!why.empty()) where = fmt::format("{} field '{}' {}", object, f.name, why);
  }
  for (const ExtraField& e : o.extra)
    if (where.empty() && first_ill_formed_utf8(e.key))
      where = fmt::format("{} has an unknown field named '{}', which is not UTF-8", object,
                          printable_utf8(e.key));
}

/// @return where the first value of the plan that JSON cannot hold is, and why, or "".
std::string first_unwritable(const Plan& plan) {
  std::string where;
  find_unwritable(plan.site, "the site", where);
  for_each_list(plan, [&](const auto& objects, ObjectKind kind) {
    for (const auto& o : objects)
      find_unwritable(o, fmt::format("{} '{}'", to_string(kind), printable_utf8(o.id)), where);
  });
  return where;
}

}  // namespace

Result<Plan> read_plan_text(std::string_view text, std::string_view file, Report* report) {
  Report found;
  Plan plan = io_detail::read_plan_document(text, file, found);
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
  const bool v2 = uses_version2(plan);
  std::string out = "{\n  \"format\": \"roomcad-plan\",\n  \"version\": ";
  out += v2 ? "2" : "1";
  out += ",\n  \"units\": \"m\",\n  \"site\": {";
  LineWriter(out).object(plan.site);
  out += '}';
  if (v2) write_array(out, "levels", plan.levels);
  write_array(out, "walls", plan.walls);
  write_array(out, "openings", plan.openings);
  if (v2) write_array(out, "slabs", plan.slabs);
  if (!plan.obstructions.empty()) write_array(out, "obstructions", plan.obstructions);
  if (!plan.rooms.empty()) write_array(out, "rooms", plan.rooms);  // only where named
  write_array(out, "lights", plan.lights);
  write_array(out, "cameras", plan.cameras);
  // Top-level unknown fields: one per line after the known ones.
  std::vector<std::string_view> written{kTopLevelKeys.begin(), kTopLevelKeys.end()};
  if (!v2)
    std::erase_if(written, [](std::string_view k) {
      return k == "levels" || k == "slabs" || k == "obstructions";
    });
  for (const ExtraField* e : writable_extras(plan.extra, written)) {
    out += ",\n  ";
    append_string(out, e->key);
    out += ": " + e->json;
  }
  out += "\n}\n";
  return out;
}

Status write_plan_file(const Plan& plan, const std::filesystem::path& path) {
  if (const std::string where = first_unwritable(plan); !where.empty())
    return Status::failure(Code::invalid_value, "cannot write " + path.string() + ": " + where +
                                                    " (JSON cannot hold it)");
  return write_file_atomically(path, write_plan_text(plan));
}

}  // namespace roomcad
