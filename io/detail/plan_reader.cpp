#include "io/detail/plan_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "io/detail/json_text.h"
#include "modeling/nearest_name.h"

namespace roomcad::io_detail {
namespace {

template <class E>
struct EnumName {
  std::string_view name;
  E value;
};

constexpr EnumName<OpeningType> kOpeningTypes[] = {{"door", OpeningType::door},
                                                   {"window", OpeningType::window}};
constexpr EnumName<Hinge> kHinges[] = {{"left", Hinge::left}, {"right", Hinge::right}};
constexpr EnumName<Swing> kSwings[] = {{"in", Swing::in}, {"out", Swing::out}};
constexpr EnumName<LightType> kLightTypes[] = {{"directional", LightType::directional}};
constexpr EnumName<Projection> kProjections[] = {{"perspective", Projection::perspective},
                                                 {"orthographic", Projection::orthographic}};

/// How a found value is shown in a message.
std::string describe(const Json& v) {
  switch (v.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array:
      return v.empty() ? "an empty array"
                       : "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " item" : " items");
    case Json::value_t::string: {
      std::string s = canonical_text(v);
      if (s.size() > 42) {
        std::size_t cut = 40;
        while (cut > 1 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // whole characters
        s = s.substr(0, cut) + "...\"";
      }
      return s;
    }
    default: return canonical_text(v);
  }
}

/// Reads one JSON document into a Plan; every problem goes to the report.
class PlanReader {
 public:
  PlanReader(const PositionedJson& doc, std::string_view text, std::string_view file,
             Report& report)
      : doc_(doc), text_(text), file_(file), report_(report), cursor_(text) {}

  Plan read() {
    Plan plan;
    const Json& root = doc_.root;
    if (!root.is_object()) {
      wrong_type("", "an object (a roomcad plan)", root);
      return plan;
    }
    scale_ = units_scale(root);
    for (auto it = root.begin(); it != root.end(); ++it) {
      const std::string& key = it.key();
      const Json& v = *it;
      const std::string p = pointer_child("", key);
      if (key == "format") {
        read_format(v, p);
      } else if (key == "version") {
        read_version(v, p);
      } else if (key == "units") {
        read_units(v, p);
      } else if (key == "site") {
        read_site(v, p, plan.site);
      } else if (key == "walls") {
        read_array(v, p, plan.walls, &PlanReader::read_wall);
      } else if (key == "openings") {
        read_array(v, p, plan.openings, &PlanReader::read_opening);
      } else if (key == "lights") {
        read_array(v, p, plan.lights, &PlanReader::read_light);
      } else if (key == "cameras") {
        read_array(v, p, plan.cameras, &PlanReader::read_camera);
      } else {
        unknown(key, v, p, plan.extra,
                {"format", "version", "units", "site", "walls", "openings", "lights", "cameras"});
      }
    }
    return plan;
  }

 private:
  // ---- diagnostics ----

  void report(Severity severity, Code code, const std::string& pointer, bool at_key,
              const std::string& what, std::string fix = {}) {
    const auto& offsets = at_key ? doc_.key_offsets : doc_.value_offsets;
    const auto found = offsets.find(pointer);
    const std::size_t offset = found == offsets.end() ? 0 : found->second;
    const LineColumn at = cursor_.at(offset);
    Diagnostic d;
    d.severity = severity;
    d.code = code;
    d.objects = objects_;
    d.message = std::string(file_) + ':' + std::to_string(at.line) + ':' +
                std::to_string(at.column) + ": " + (pointer.empty() ? "" : pointer + ": ") + what;
    d.fix = std::move(fix);
    d.location = Location{std::string(file_), pointer, at.line, at.column};
    report_.add(std::move(d));
  }

  void wrong_type(const std::string& p, std::string_view expected, const Json& found) {
    report(Severity::error, Code::parse_error, p, false,
           "expected " + std::string(expected) + ", found " + describe(found));
  }

  void invalid(const std::string& p, const std::string& what, std::string fix = {}) {
    report(Severity::error, Code::invalid_value, p, false, what, std::move(fix));
  }

  void missing(const std::string& object_pointer, std::string_view key, std::string_view what) {
    report(Severity::error, Code::parse_error, object_pointer, false,
           "missing required field \"" + std::string(key) + "\" (" + std::string(what) + ")");
  }

  void unknown(const std::string& key, const Json& v, const std::string& p, ExtraFields& extra,
               std::initializer_list<std::string_view> known) {
    std::string what = "unknown field \"" + key + "\"; its value is kept as is";
    std::string fix = "remove the field if it is a mistake";
    if (const auto best = nearest_name(key, {known.begin(), known.size()})) {
      what += " (did you mean \"" + std::string(*best) + "\"?)";
      fix = "rename it to \"" + std::string(*best) + "\"";
    }
    report(Severity::warning, Code::unknown_field, p, true, what, std::move(fix));
    extra.push_back(ExtraField{key, canonical_text(v)});
  }

  // ---- top level ----

  double units_scale(const Json& root) const {
    const auto it = root.find("units");
    if (it == root.end() || !it->is_string()) return 1.0;
    if (*it == "cm") return 100.0;
    if (*it == "mm") return 1000.0;
    return 1.0;
  }

  void read_format(const Json& v, const std::string& p) {
    if (!v.is_string()) return wrong_type(p, "the string \"roomcad-plan\"", v);
    if (v != "roomcad-plan")
      invalid(p, "unsupported format " + describe(v) + "; roomcad reads \"roomcad-plan\"",
              "set \"format\": \"roomcad-plan\"");
  }

  void read_version(const Json& v, const std::string& p) {
    if (!v.is_number()) return wrong_type(p, "the number 1", v);
    if (v.get<double>() != 1.0)
      invalid(p, "unsupported version " + describe(v) + "; this roomcad reads version 1");
  }

  void read_units(const Json& v, const std::string& p) {
    if (!v.is_string()) return wrong_type(p, "\"m\", \"cm\" or \"mm\"", v);
    if (v != "m" && v != "cm" && v != "mm")
      invalid(p, "unsupported units " + describe(v) + "; expected \"m\", \"cm\" or \"mm\"");
  }

  template <class T>
  void read_array(const Json& v, const std::string& p, std::vector<T>& out,
                  T (PlanReader::*read_one)(const Json&, const std::string&)) {
    if (!v.is_array()) return wrong_type(p, "an array", v);
    if (v.size() > kMaxPlanObjects)
      return invalid(p, std::to_string(v.size()) + " objects; a plan may hold at most " +
                            std::to_string(kMaxPlanObjects) +
                            " of each kind (walls, openings, lights, cameras)",
                     "split the plan into several files");
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string ip = pointer_child(p, i);
      if (!v[i].is_object()) {
        wrong_type(ip, "an object", v[i]);
        continue;
      }
      objects_.clear();
      if (const auto id = v[i].find("id"); id != v[i].end() && id->is_string())
        objects_.push_back(id->get<std::string>());
      out.push_back((this->*read_one)(v[i], ip));
      objects_.clear();
    }
  }

  // ---- fields ----

  /// Reads a number; lengths are converted to metres.
  void number(const Json& v, const std::string& p, double& out, bool length) {
    if (!v.is_number()) return wrong_type(p, "a number", v);
    out = v.get<double>();
    if (length && scale_ != 1.0) out /= scale_;
  }
  void length(const Json& v, const std::string& p, double& out) { number(v, p, out, true); }

  /// Reads an array of exactly n numbers.
  void numbers(const Json& v, const std::string& p, double* out, std::size_t n, bool length,
               std::string_view shape) {
    if (!v.is_array() || v.size() != n) return wrong_type(p, shape, v);
    for (std::size_t i = 0; i < n; ++i) number(v[i], pointer_child(p, i), out[i], length);
  }
  void point2(const Json& v, const std::string& p, Point2& out) {
    double xy[2] = {out.x, out.y};
    numbers(v, p, xy, 2, true, "an array of 2 numbers [x, y]");
    out = {xy[0], xy[1]};
  }
  void vec3(const Json& v, const std::string& p, Vec3& out, bool length) {
    double xyz[3] = {out.x, out.y, out.z};
    numbers(v, p, xyz, 3, length, "an array of 3 numbers [x, y, z]");
    out = {xyz[0], xyz[1], xyz[2]};
  }

  void color(const Json& v, const std::string& p, Color& out) {
    if (!v.is_string()) return wrong_type(p, "a colour string \"#rrggbb\"", v);
    if (const auto c = parse_color(v.get_ref<const std::string&>())) {
      out = *c;
    } else {
      invalid(p, "expected a colour \"#rrggbb\" (6 hexadecimal digits), found " + describe(v));
    }
  }

  template <class E, std::size_t N>
  void enumeration(const Json& v, const std::string& p, E& out, const EnumName<E> (&names)[N]) {
    std::string expected;
    for (std::size_t i = 0; i < N; ++i)
      expected += (i == 0 ? "\"" : i + 1 == N ? " or \"" : ", \"") + std::string(names[i].name) + '"';
    if (!v.is_string()) return wrong_type(p, expected, v);
    for (const auto& n : names) {
      if (v == n.name) {
        out = n.value;
        return;
      }
    }
    invalid(p, "unknown value " + describe(v) + "; expected " + expected);
  }

  void cells(const Json& v, const std::string& p, std::array<std::int64_t, 2>& out) {
    if (!v.is_array() || v.size() != 2)
      return wrong_type(p, "an array of 2 positive integers [nx, ny]", v);
    for (std::size_t i = 0; i < 2; ++i) {
      const Json& c = v[i];
      const std::string cp = pointer_child(p, i);
      const bool integral = c.is_number_integer() ||
                            (c.is_number_float() && std::trunc(c.get<double>()) == c.get<double>());
      if (!integral) {
        wrong_type(cp, "a positive integer", c);
      } else if (c.is_number_unsigned() ? c.get<std::uint64_t>() > 1'000'000'000
                                        : c.get<double>() > 1e9) {
        invalid(cp, "cell count " + describe(c) + " is too large (at most 1000000000)");
      } else if (c.get<double>() < 1) {
        invalid(cp, "expected a positive integer, found " + describe(c),
                "give the site at least one cell along each axis");
      } else {
        out[i] = static_cast<std::int64_t>(c.get<double>());
      }
    }
  }

  // ---- objects ----

  void read_site(const Json& v, const std::string& p, Site& site) {
    objects_.clear();
    if (!v.is_object()) return wrong_type(p, "an object", v);
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const std::string fp = pointer_child(p, k);
      if (k == "origin") point2(*it, fp, site.origin);
      else if (k == "cells") cells(*it, fp, site.cells);
      else if (k == "cell_size") length(*it, fp, site.cell_size);
      else if (k == "max_height") length(*it, fp, site.max_height);
      else if (k == "tolerance") length(*it, fp, site.tolerance);
      else if (k == "floor_color") color(*it, fp, site.floor_color);
      else unknown(k, *it, fp, site.extra,
                   {"origin", "cells", "cell_size", "max_height", "tolerance", "floor_color"});
    }
  }

  Wall read_wall(const Json& v, const std::string& p) {
    Wall w;
    bool has[3] = {};
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const std::string fp = pointer_child(p, k);
      if (k == "id") has[0] = true, id(*it, fp, w.id);
      else if (k == "from") has[1] = true, point2(*it, fp, w.from);
      else if (k == "to") has[2] = true, point2(*it, fp, w.to);
      else if (k == "thickness") length(*it, fp, w.thickness);
      else if (k == "height") length(*it, fp, w.height);
      else if (k == "base") length(*it, fp, w.base);
      else if (k == "color") color(*it, fp, w.color);
      else unknown(k, *it, fp, w.extra,
                   {"id", "from", "to", "thickness", "height", "base", "color"});
    }
    if (!has[0]) missing(p, "id", "a unique string");
    if (!has[1]) missing(p, "from", "the start of the centre line, [x, y]");
    if (!has[2]) missing(p, "to", "the end of the centre line, [x, y]");
    return w;
  }

  Opening read_opening(const Json& v, const std::string& p) {
    Opening o;
    bool has_id = false, has_wall = false, has_offset = false;
    std::optional<double> width, height, sill;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const std::string fp = pointer_child(p, k);
      if (k == "id") has_id = true, id(*it, fp, o.id);
      else if (k == "type") enumeration(*it, fp, o.type, kOpeningTypes);
      else if (k == "wall") has_wall = true, id(*it, fp, o.wall);
      else if (k == "offset") has_offset = true, length(*it, fp, o.offset);
      else if (k == "width") length(*it, fp, width.emplace(o.width));
      else if (k == "height") length(*it, fp, height.emplace(o.height));
      else if (k == "sill") length(*it, fp, sill.emplace(o.sill));
      else if (k == "hinge") enumeration(*it, fp, o.hinge, kHinges);
      else if (k == "swing") enumeration(*it, fp, o.swing, kSwings);
      else unknown(k, *it, fp, o.extra,
                   {"id", "type", "wall", "offset", "width", "height", "sill", "hinge", "swing"});
    }
    const OpeningDefaults defaults = opening_defaults(o.type);
    o.width = width.value_or(defaults.width);
    o.height = height.value_or(defaults.height);
    o.sill = sill.value_or(defaults.sill);
    if (!has_id) missing(p, "id", "a unique string");
    if (!has_wall) missing(p, "wall", "the id of the wall it is cut in");
    if (!has_offset) missing(p, "offset", "its start along the wall, metres from the wall's \"from\"");
    return o;
  }

  Light read_light(const Json& v, const std::string& p) {
    Light l;
    bool has_id = false;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const std::string fp = pointer_child(p, k);
      if (k == "id") has_id = true, id(*it, fp, l.id);
      else if (k == "type") enumeration(*it, fp, l.type, kLightTypes);
      else if (k == "direction") vec3(*it, fp, l.direction, false);
      else if (k == "intensity") number(*it, fp, l.intensity, false);
      else if (k == "ambient") number(*it, fp, l.ambient, false);
      else unknown(k, *it, fp, l.extra, {"id", "type", "direction", "intensity", "ambient"});
    }
    if (!has_id) missing(p, "id", "a unique string");
    return l;
  }

  Camera read_camera(const Json& v, const std::string& p) {
    Camera c;
    bool has[3] = {};
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      const std::string fp = pointer_child(p, k);
      if (k == "id") has[0] = true, id(*it, fp, c.id);
      else if (k == "projection") enumeration(*it, fp, c.projection, kProjections);
      else if (k == "eye") has[1] = true, vec3(*it, fp, c.eye, true);
      else if (k == "target") has[2] = true, vec3(*it, fp, c.target, true);
      else if (k == "up") vec3(*it, fp, c.up, false);
      else if (k == "fov_deg") number(*it, fp, c.fov_deg, false);
      else if (k == "view_height") length(*it, fp, c.view_height);
      else unknown(k, *it, fp, c.extra,
                   {"id", "projection", "eye", "target", "up", "fov_deg", "view_height"});
    }
    if (!has[0]) missing(p, "id", "a unique string");
    if (!has[1]) missing(p, "eye", "where the camera is, [x, y, z]");
    if (!has[2]) missing(p, "target", "the point it looks at, [x, y, z]");
    return c;
  }

  void id(const Json& v, const std::string& p, std::string& out) {
    if (!v.is_string()) return wrong_type(p, "a string id", v);
    out = v.get<std::string>();
  }

  const PositionedJson& doc_;
  std::string_view text_;
  std::string_view file_;
  Report& report_;
  LineColumnCursor cursor_;  ///< diagnostics come in file order, mostly
  double scale_ = 1.0;                ///< divisor from the file's units to metres
  std::vector<std::string> objects_;  ///< id of the object being read, for diagnostics
};

}  // namespace

Plan read_plan_document(const PositionedJson& doc, std::string_view text, std::string_view file,
                        Report& report) {
  Report found;
  Plan plan = PlanReader(doc, text, file, found).read();
  // Errors of one object come in field order, then its missing fields: sort by position.
  std::vector<std::size_t> index(found.items.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  auto position = [&](std::size_t i) {
    const Location& at = *found.items[i].location;
    return std::pair(at.line, at.column);
  };
  std::stable_sort(index.begin(), index.end(),
                   [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
  for (std::size_t i : index) report.add(std::move(found.items[i]));
  return plan;
}

}  // namespace roomcad::io_detail
