// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/detail/plan_reader.h"

#include <simdjson.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/detail/json_text.h"
#include "io/detail/json_value_text.h"
#include "io/detail/positioned_json.h"
#include "io/plan_json.h"
#include "plan/nearest_name.h"
#include "plan/plan_fields.h"
#include "plan/value_text.h"

namespace roomcad::io_detail {
namespace {

namespace od = simdjson::ondemand;
using JsonType = od::json_type;

/// Rejects what simdjson lets through but a plan must not hold: a key twice in one object.
/// Fields of the table are tracked by bit, others by name (rare).
class SeenKeys {
 public:
  void add(std::size_t field_index) {
    if (seen_ >> field_index & 1u) throw Malformed{};
    seen_ |= std::uint64_t{1} << field_index;
  }
  void add(std::string_view key) {
    if (std::find(others_.begin(), others_.end(), key) != others_.end()) throw Malformed{};
    others_.emplace_back(key);
  }
  [[nodiscard]] bool has(std::size_t field_index) const { return seen_ >> field_index & 1u; }

 private:
  std::uint64_t seen_ = 0;
  std::vector<std::string> others_;
};

/// The names of an enum's values as a message lists them: "\"door\" or \"window\"".
template <class E>
std::string expected_names() {
  std::string out;
  const std::size_t n = std::size(EnumValues<E>::all);
  for (std::size_t i = 0; i < n; ++i)
    out += (i == 0       ? "\""
            : i + 1 == n ? " or \""
                         : ", \"") +
           std::string(to_string(EnumValues<E>::all[i])) + '"';
  return out;
}

class PlanReader {
 public:
  /// @param[in] json_begin  where the JSON (text from byte `base` on, padded for simdjson) starts
  PlanReader(const char* json_begin, std::size_t base) : json_begin_(json_begin), base_(base) {}

  Plan read(od::document& doc) {
    Plan plan;
    if (doc.type().value() != JsonType::object) {
      const PositionedJson whole = parse_positioned_json(doc.raw_json().value());
      if (whole.error) throw Malformed{};
      report(Severity::error, Code::parse_error, offset_of(doc.raw_json_token().value().data()),
             "expected an object (a roomcad plan), found " + describe_json(whole.root));
      flush({});
      return plan;
    }
    od::object root = doc.get_object().value();
    read_preamble(root);
    for (od::field field : root) read_top_level(std::move(field), plan);
    if (doc.current_location().error() != simdjson::OUT_OF_BOUNDS) throw Malformed{};
    complete_wall_heights(plan);
    return plan;
  }

 private:
  // ---- where we are: a JSON pointer kept as tokens, turned into text only for a message ----

  struct Token {
    std::string_view key;  ///< into the text or simdjson's string buffer: both outlive the read
    std::size_t index = 0;
    bool is_index = false;
  };

  std::string pointer() const {
    std::string p;
    for (const Token& t : path_)
      p = t.is_index ? pointer_child(p, t.index) : pointer_child(p, t.key);
    return p;
  }

  /// Steps into a key or index for the duration of a scope.
  class Step {
   public:
    Step(PlanReader& r, std::string_view key) : r_(r) { r_.path_.push_back({key, 0, false}); }
    Step(PlanReader& r, std::size_t index) : r_(r) { r_.path_.push_back({{}, index, true}); }
    ~Step() { r_.path_.pop_back(); }
    Step(const Step&) = delete;
    Step& operator=(const Step&) = delete;

   private:
    PlanReader& r_;
  };

  std::size_t offset_of(const char* at) const {
    return static_cast<std::size_t>(at - json_begin_) + base_;
  }
  std::size_t offset_of(od::value& v) { return offset_of(v.raw_json_token().data()); }

  // ---- diagnostics ----

 public:
  /// A problem found, placed by byte offset; its line, column and message are made at the end,
  /// in one pass over the text (problems arrive out of order: a missing field is reported at its
  /// object's start after the object's fields).
  struct Problem {
    std::size_t offset = 0;
    std::string pointer;
    std::string what;
    Diagnostic diagnostic;  ///< severity, code, objects and fix so far
  };
  std::vector<Problem> take_problems() { return std::move(problems_); }

 private:
  void report(Severity severity, Code code, std::size_t offset, std::string what,
              std::string fix = {}) {
    Problem p{offset, pointer(), std::move(what), {}};
    p.diagnostic.severity = severity;
    p.diagnostic.code = code;
    p.diagnostic.fix = std::move(fix);
    pending_.push_back(std::move(p));
  }
  void wrong_type(od::value& v, std::string_view expected) {
    const std::size_t at = offset_of(v);
    report(Severity::error, Code::parse_error, at,
           "expected " + std::string(expected) + ", found " + describe(v));
  }
  void invalid(std::size_t at, std::string what, std::string fix = {}) {
    report(Severity::error, Code::invalid_value, at, std::move(what), std::move(fix));
  }
  /// Keeps the problems of one object, naming the object by its id.
  void flush(const std::string& id) {
    for (Problem& p : pending_) {
      if (!id.empty()) p.diagnostic.objects = {id};
      problems_.push_back(std::move(p));
    }
    pending_.clear();
  }

  void unknown(std::string_view key, od::value& v, std::size_t key_offset, ExtraFields& extra,
               const std::vector<std::string_view>& known, std::string_view why = {}) {
    std::string what = "unknown field \"" + std::string(key) + "\"; its value is kept as is";
    std::string fix = "remove the field if it is a mistake";
    if (!why.empty()) {
      what = "\"" + std::string(key) + "\" " + std::string(why) + "; its value is kept as is";
      fix = "set \"version\": 2 to use it";
    } else if (const auto best = nearest_name(key, known)) {
      what += " (did you mean \"" + std::string(*best) + "\"?)";
      fix = "rename it to \"" + std::string(*best) + "\"";
    }
    report(Severity::warning, Code::unknown_field, key_offset, what, std::move(fix));
    const PositionedJson value = parse_positioned_json(raw_json(v), path_.size());
    if (value.error) throw Malformed{};
    extra.push_back(ExtraField{std::string(key), canonical_text(value.root)});
  }

  // ---- the top level ----

  /// Reads `version` and `units` first: they decide how every other field is read.
  void read_preamble(od::object& root) {
    od::value v;
    if (find(root, "version", v) && v.type().value() == JsonType::number &&
        v.get_double().value() == 2.0)
      version_ = 2;
    if (find(root, "units", v) && v.type().value() == JsonType::string) {
      // Kept for read_units: simdjson unescapes a string into a buffer sized for each string
      // once, and a second unescape of the same one can run past it (fuzz_plan_json: a long
      // "units" string corrupted the heap).
      units_ = std::string(v.get_string().value());
      scale_ = *units_ == "cm" ? 100.0 : *units_ == "mm" ? 1000.0 : 1.0;
    }
    root.reset().value();
  }

  /// @return whether `root` has the key (then `out` is its value). Malformed JSON throws.
  static bool find(od::object& root, std::string_view key, od::value& out) {
    const simdjson::error_code error = root.find_field_unordered(key).get(out);
    if (error == simdjson::NO_SUCH_FIELD) return false;
    if (error) throw Malformed{};
    return true;
  }

  void read_top_level(od::field field, Plan& plan) {
    const std::size_t key_offset = offset_of(field.key().raw()) - 1;  // before unescaping it
    const std::string_view key = field.unescaped_key().value();
    top_keys_.add(key);
    od::value v = field.value();
    Step step(*this, key);
    const bool v2 = version_ == 2;
    if (key == "format") read_format(v);
    else if (key == "version") read_version(v);
    else if (key == "units") read_units(v);
    else if (key == "site") read_site(v, plan.site);
    else if (key == "walls") read_list(v, plan.walls);
    else if (key == "openings") read_list(v, plan.openings);
    else if (key == "rooms") read_list(v, plan.rooms);
    else if (key == "lights") read_list(v, plan.lights);
    else if (key == "cameras") read_list(v, plan.cameras);
    else if (v2 && key == "levels") read_list(v, plan.levels);
    else if (v2 && key == "slabs") read_list(v, plan.slabs);
    else if (v2 && key == "obstructions") read_list(v, plan.obstructions);
    else {
      const bool later = key == "levels" || key == "slabs" || key == "obstructions";
      unknown(key, v, key_offset, plan.extra, {kTopLevelKeys.begin(), kTopLevelKeys.end()},
              later ? "is a version 2 field and this file is version 1" : "");
    }
    flush({});
  }

  void read_format(od::value& v) {
    std::string_view s;
    if (v.type().value() != JsonType::string) return wrong_type(v, "the string \"roomcad-plan\"");
    const std::size_t at = offset_of(v);
    if (v.get_string().get(s) || s != "roomcad-plan")
      invalid(at, "unsupported format " + quote_for_message(s) + "; roomcad reads \"roomcad-plan\"",
              "set \"format\": \"roomcad-plan\"");
  }

  void read_version(od::value& v) {
    if (v.type().value() != JsonType::number) return wrong_type(v, "the number 1 or 2");
    const std::size_t at = offset_of(v);
    const std::string token = describe(v);
    const double version = v.get_double().value();
    if (version != 1.0 && version != 2.0)
      invalid(at, "unsupported version " + token + "; this roomcad reads versions 1 and 2");
  }

  void read_units(od::value& v) {
    if (v.type().value() != JsonType::string) return wrong_type(v, "\"m\", \"cm\" or \"mm\"");
    const std::size_t at = offset_of(v);
    // The first "units" was unescaped by read_preamble; a repeated key is read here, once.
    const std::string s =
        units_ ? *std::exchange(units_, std::nullopt) : std::string(v.get_string().value());
    if (s != "m" && s != "cm" && s != "mm")
      invalid(at,
              "unsupported units " + quote_for_message(s) + "; expected \"m\", \"cm\" or \"mm\"");
  }

  // ---- objects, through the field tables ----

  template <class Object>
  void read_list(od::value& v, std::vector<Object>& out) {
    if (v.type().value() != JsonType::array) return wrong_type(v, "an array");
    const std::size_t at = offset_of(v);
    const std::size_t problems_before = problems_.size();
    std::size_t i = 0;
    for (auto item : v.get_array()) {
      Step step(*this, i++);
      od::value object = item.value();
      if (i > kMaxPlanObjects) continue;  // counted, not read: the whole array is refused
      if (object.type().value() != JsonType::object) {
        wrong_type(object, "an object");
        flush({});
        continue;
      }
      out.push_back(read_object<Object>(object));
    }
    if (i <= kMaxPlanObjects) return;
    out.clear();
    problems_.resize(problems_before);  // one problem for the array, not one per object
    invalid(at,
            std::to_string(i) + " objects; a plan may hold at most " +
                std::to_string(kMaxPlanObjects) +
                " of each kind (levels, walls, openings, slabs, lights, cameras)",
            "split the plan into several files");
    flush({});
  }

  void read_site(od::value& v, Site& site) {
    if (v.type().value() != JsonType::object) return wrong_type(v, "an object");
    site = read_object<Site>(v, std::move(site));
  }

  template <class Object>
  Object read_object(od::value& v, Object object = {}) {
    const auto fields = fields_of<Object>();
    const std::size_t at = offset_of(v);
    SeenKeys seen;
    for (od::field member : v.get_object()) {
      const std::size_t key_offset = offset_of(member.key().raw()) - 1;  // before unescaping it
      const std::string_view key = member.unescaped_key().value();
      od::value value = member.value();
      Step step(*this, key);
      const Field<Object>* field = find_field<Object>(key);
      const bool v1_only = field && field->presence == Presence::version2 && version_ == 1;
      if (field && !v1_only) {
        seen.add(static_cast<std::size_t>(field - fields.data()));
        const bool length = field->unit == Unit::metre;
        std::visit([&](auto m) { read_value(value, object.*m, length); }, field->member);
        continue;
      }
      seen.add(key);
      unknown(key, value, key_offset, object.extra, field_names_of<Object>(),
              v1_only ? "is a version 2 field and this file is version 1" : "");
    }
    for (const Field<Object>& f : fields)
      if (f.presence == Presence::required &&
          !seen.has(static_cast<std::size_t>(&f - fields.data())))
        report(
            Severity::error, Code::parse_error, at,
            "missing required field \"" + std::string(f.name) + "\" (" + std::string(f.hint) + ")");
    complete_defaults(object, seen);
    flush(object_id(object));
    return object;
  }

  static std::string object_id(const Site&) { return {}; }
  static std::string object_id(const GeoLocation&) { return {}; }
  template <class Object>
  static std::string object_id(const Object& o) {
    return o.id;
  }

  /// Defaults that depend on another field: an opening's size and sill depend on its type.
  void complete_defaults(Opening& o, const SeenKeys& seen) {
    const OpeningDefaults d = opening_defaults(o.type);
    auto field_index = [](std::string_view name) {
      return static_cast<std::size_t>(find_field<Opening>(name) - fields_of<Opening>().data());
    };
    if (!seen.has(field_index("width"))) o.width = d.width;
    if (!seen.has(field_index("height"))) o.height = d.height;
    if (!seen.has(field_index("sill"))) o.sill = d.sill;
  }
  void complete_defaults(Wall& w, const SeenKeys& seen) {
    const auto height =
        static_cast<std::size_t>(find_field<Wall>("height") - fields_of<Wall>().data());
    if (!w.level.empty() && !seen.has(height)) walls_without_height_.push_back(wall_count_);
    ++wall_count_;
  }
  template <class Object>
  void complete_defaults(Object&, const SeenKeys&) {}

  /// A wall of a level that gives no height of its own takes the level's (version 2).
  void complete_wall_heights(Plan& plan) const {
    for (const std::size_t i : walls_without_height_) {
      Wall& w = plan.walls[i];
      for (const Level& l : plan.levels)
        if (l.id == w.level) w.height = l.height;
    }
  }

  // ---- values, by the member's type ----

  /// Reads a number (lengths converted to metres). @return whether it was one.
  bool read_number(od::value& v, double& out, bool length) {
    if (v.type().value() != JsonType::number) {
      wrong_type(v, "a number");
      return false;
    }
    out = v.get_double().value();  // a number too large for a double throws: Malformed
    if (length && scale_ != 1.0) out /= scale_;
    return true;
  }

  /// Reads an array of exactly n numbers into out[0..n). A wrong count is one problem on the
  /// array; otherwise each element that is not a number is one. @return whether it was one.
  bool read_numbers(od::value& v, double* out, std::size_t n, bool length, std::string_view shape) {
    if (v.type().value() != JsonType::array) {
      wrong_type(v, shape);
      return false;
    }
    const std::size_t at = offset_of(v);
    const std::size_t problems_before = pending_.size();
    std::vector<double> values;
    for (auto item : v.get_array()) {
      od::value e = item.value();
      Step step(*this, values.size());
      double x = 0.0;
      values.push_back(values.size() < n && read_number(e, x, length) ? x : 0.0);
    }
    if (values.size() != n) {
      pending_.resize(problems_before);
      report(Severity::error, Code::parse_error, at,
             "expected " + std::string(shape) + ", found " + count_text(values.size()));
      return false;
    }
    if (pending_.size() != problems_before) return false;
    std::copy(values.begin(), values.end(), out);
    return true;
  }

  void read_value(od::value& v, double& out, bool length) { read_number(v, out, length); }
  void read_value(od::value& v, std::optional<GeoLocation>& out, bool) {
    if (v.type().value() != JsonType::object) return wrong_type(v, "an object");
    out = read_object<GeoLocation>(v);
  }
  void read_value(od::value& v, std::optional<double>& out, bool length) {
    double x = 0.0;
    if (read_number(v, x, length)) out = x;
  }
  void read_value(od::value& v, Point2& out, bool length) {
    double xy[2];
    if (read_numbers(v, xy, 2, length, "an array of 2 numbers [x, y]")) out = {xy[0], xy[1]};
  }
  void read_value(od::value& v, Vec3& out, bool length) {
    double xyz[3];
    if (read_numbers(v, xyz, 3, length, "an array of 3 numbers [x, y, z]"))
      out = {xyz[0], xyz[1], xyz[2]};
  }
  void read_value(od::value& v, Color& out, bool) {
    if (v.type().value() != JsonType::string) return wrong_type(v, "a colour string \"#rrggbb\"");
    const std::size_t at = offset_of(v);
    const std::string_view text = v.get_string().value();
    if (const auto c = parse_color(text)) out = *c;
    else
      invalid(at, "expected a colour \"#rrggbb\" (6 hexadecimal digits), found " +
                      quote_for_message(text));
  }
  void read_value(od::value& v, std::string& out, bool) {
    if (v.type().value() != JsonType::string) return wrong_type(v, "a string id");
    out = std::string(v.get_string().value());
  }
  template <class E>
  requires std::is_enum_v<E>
  void read_value(od::value& v, E& out, bool) {
    if (v.type().value() != JsonType::string) return wrong_type(v, expected_names<E>());
    const std::size_t at = offset_of(v);
    const std::string_view text = v.get_string().value();
    if (const auto e = parse_enum<E>(text)) out = *e;
    else
      invalid(at, "unknown value " + quote_for_message(text) + "; expected " + expected_names<E>());
  }
  void read_value(od::value& v, std::array<std::int64_t, 2>& out, bool) {
    if (v.type().value() != JsonType::array)
      return wrong_type(v, "an array of 2 positive integers [nx, ny]");
    const std::size_t at = offset_of(v);
    std::size_t i = 0;
    for (auto item : v.get_array()) {
      od::value c = item.value();
      if (i < 2) read_cell(c, out[i], i);
      ++i;
    }
    if (i != 2)
      report(Severity::error, Code::parse_error, at,
             "expected an array of 2 positive integers [nx, ny], found " + count_text(i));
  }
  void read_cell(od::value& c, std::int64_t& out, std::size_t i) {
    Step step(*this, i);
    const std::size_t at = offset_of(c);
    double x = 0.0;
    const bool number = c.type().value() == JsonType::number;
    if (number) x = c.get_double().value();
    if (!number || std::trunc(x) != x) {
      report(Severity::error, Code::parse_error, at,
             "expected a positive integer, found " + describe_number_token(c, x, number));
    } else if (x > 1e9) {
      invalid(at, "cell count " + describe_number_token(c, x, true) +
                      " is too large (at most 1000000000)");
    } else if (x < 1) {
      invalid(at, "expected a positive integer, found " + describe_number_token(c, x, true),
              "give the site at least one cell along each axis");
    } else {
      out = static_cast<std::int64_t>(x);
    }
  }
  /// A number as the message shows it (canonical), or the value described when not a number.
  std::string describe_number_token(od::value& c, double x, bool number) {
    if (!number) return describe(c);
    std::string out;
    append_number(out, x);
    return out;
  }
  void read_value(od::value& v, Polygon& out, bool length) {
    if (v.type().value() != JsonType::array)
      return wrong_type(v, "an array of points [[x, y], ...]");
    Polygon polygon;
    bool ok = true;
    for (auto item : v.get_array()) {
      od::value p = item.value();
      Step step(*this, polygon.size());
      double xy[2] = {0.0, 0.0};
      ok = read_numbers(p, xy, 2, length, "an array of 2 numbers [x, y]") && ok;
      polygon.push_back({xy[0], xy[1]});
    }
    if (ok) out = std::move(polygon);
  }
  void read_value(od::value& v, std::vector<Polygon>& out, bool length) {
    if (v.type().value() != JsonType::array)
      return wrong_type(v, "an array of polygons [[[x, y], ...], ...]");
    std::vector<Polygon> polygons;
    for (auto item : v.get_array()) {
      od::value p = item.value();
      Step step(*this, polygons.size());
      read_value(p, polygons.emplace_back(), length);
    }
    out = std::move(polygons);
  }

  const char* json_begin_;
  const std::size_t base_;  ///< offset of json_begin_ in the file (past a byte-order mark)
  std::vector<Token> path_;
  std::vector<Problem> pending_;   ///< the current object's problems, until its id is known
  std::vector<Problem> problems_;  ///< all the others
  SeenKeys top_keys_;
  int version_ = 1;
  double scale_ = 1.0;                ///< divisor from the file's units to metres
  std::optional<std::string> units_;  ///< the first "units" string, until read_units takes it
  std::vector<std::size_t> walls_without_height_;
  std::size_t wall_count_ = 0;
};

/// The one problem of a text that is not the JSON the reader accepts, as the positioned
/// parser words it (line, column, pointer; a number too large for a double is invalid_value).
Diagnostic malformed_json(std::string_view text, std::string_view file) {
  const PositionedJson doc = parse_positioned_json(text);
  JsonSyntaxError error = doc.error.value_or(JsonSyntaxError{0, "", "not a JSON document", false});
  const LineColumn at = line_column_at(text, error.offset);
  Diagnostic d;
  d.code = error.not_finite ? Code::invalid_value : Code::parse_error;
  d.message = std::string(file) + ':' + std::to_string(at.line) + ':' + std::to_string(at.column) +
              ": " + (error.pointer.empty() ? "" : error.pointer + ": ") + error.message;
  if (error.not_finite) d.fix = "write a finite number (metres, or the file's units)";
  d.location = Location{std::string(file), error.pointer, at.line, at.column};
  return d;
}

/// The reader's problems in file order, each given its line, column and message: one forward
/// pass over the text for all of them.
void place_problems(std::vector<PlanReader::Problem> problems, std::string_view text,
                    std::string_view file, Report& report) {
  std::stable_sort(problems.begin(), problems.end(),
                   [](const auto& a, const auto& b) { return a.offset < b.offset; });
  LineColumnCursor cursor(text);
  for (PlanReader::Problem& p : problems) {
    const LineColumn at = cursor.at(p.offset);
    Diagnostic& d = p.diagnostic;
    d.message = std::string(file) + ':' + std::to_string(at.line) + ':' +
                std::to_string(at.column) + ": " + (p.pointer.empty() ? "" : p.pointer + ": ") +
                p.what;
    d.location = Location{std::string(file), p.pointer, at.line, at.column};
    report.add(std::move(d));
  }
}

}  // namespace

Plan read_plan_document(std::string_view text, std::string_view file, Report& report) {
  const std::size_t base = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;  // a UTF-8 byte-order mark
  try {
    simdjson::padded_string json(text.substr(base));
    od::parser parser;
    od::document doc = parser.iterate(json).value();
    PlanReader reader(json.data(), base);
    Plan plan = reader.read(doc);
    place_problems(reader.take_problems(), text, file, report);
    return plan;
  } catch (const simdjson::simdjson_error&) {
  } catch (const Malformed&) {}
  report.add(malformed_json(text, file));
  return {};
}

}  // namespace roomcad::io_detail
