// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad.Plan: reading and saving, validation, edits, building, rendering and drawing, each
// through the library function the command line calls (io/plan_json.h, io/plan_check.h,
// plan/plan_edit.h, solid/build_model.h, render/render_request.h, io/plan_drawing.h).
#include <filesystem>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "daylight/insolation_rule.h"
#include "daylight/sun_at.h"
#include "io/plan_check.h"
#include "io/plan_drawing.h"
#include "io/plan_json.h"
#include "io/rule_set_file.h"
#include "io/text_file.h"
#include "plan/plan_add.h"
#include "plan/plan_objects.h"
#include "python/py_error.h"
#include "python/py_plan_values.h"
#include "python/py_site.h"
#include "python/py_types.h"
#include "render/render_request.h"
#include "repair/repair.h"
#include "repair/repair_report.h"
#include "solid/build_model.h"
#include "validation/report_diff.h"
#include "validation/report_format.h"
#include "validation/validate.h"

namespace py = pybind11;

namespace roomcad::python {
namespace {

py::object json_loads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

PyPlan read_text(const std::string& text, const std::string& file, std::string name) {
  PyPlan out;
  Report reading;
  std::optional<Result<Plan>> read;
  {
    py::gil_scoped_release free;
    read.emplace(read_plan_text(text, file, &reading));
  }
  out.plan = take(std::move(*read));
  out.reading = std::move(reading);
  out.name = std::move(name);
  return out;
}

PyPlan load(const std::filesystem::path& path) {
  PyPlan out = read_text(take(read_text_file(path)), path.string(), path.filename().string());
  out.file = path.string();
  return out;
}

Report check(const PyPlan& self, const RuleSet& rules = {}) {
  py::gil_scoped_release free;
  Report report = check_plan(self.plan, self.reading ? &*self.reading : nullptr, rules);
  add_insolation_findings(self.plan, rules, report);
  return report;
}

}  // namespace

void require_valid(const PyPlan& self, bool force, std::string_view verb) {
  if (force) return;
  const Report report = check(self);
  if (report.ok()) return;
  const Diagnostic& first = report.items.front();  // errors come first
  raise(Error{first.code,
              fmt::format("{}: the plan has {}; the first: {} (fix them, or pass force=True)", verb,
                          format_report_summary(report), first.message),
              first.location});
}

namespace {

/// Applies `edit` to a copy of the plan and keeps it unless it introduces errors (then raises
/// edit_refused, unless `force`): what every `roomcad` edit command does (cli/edit_session.h).
/// The edit's Error, returned or thrown (make_edit), is raised as roomcad.Error.
template <class Edit>
EditSummary apply_edit(PyPlan& self, bool force, Edit&& edit) {
  Plan edited = self.plan;
  Result<EditSummary> made = make_edit(edit, edited);
  if (!made) raise(made.error());
  EditSummary summary = std::move(made).value();
  if (edited == self.plan) return summary;
  if (!force) {
    Report fresh;
    {
      py::gil_scoped_release free;
      fresh = introduced_errors(validate(self.plan), validate(edited));
    }
    if (!fresh.ok())
      raise(Error{Code::edit_refused,
                  fmt::format("refused: the edit introduces {}: {} (force=True keeps it)",
                              format_report_summary(fresh), fresh.items.front().message)});
  }
  self.plan = std::move(edited);
  self.reading.reset();  // its places and unknown fields may be gone
  return summary;
}

std::optional<Point2> about_point(const std::optional<std::pair<double, double>>& about) {
  if (!about) return std::nullopt;
  return Point2{about->first, about->second};
}

Parts parts_of(const std::string& parts) {
  return take(parse_parts(parts == "all" ? kAllParts : parts));
}

// Made in place on the heap and handed to Python as it is: an OpenMesh mesh has no move
// constructor (its kernel declares a destructor), so every "move" of a Model copies its
// meshes, which cost 10% of a build.
std::unique_ptr<PyModel> build(const PyPlan& self, bool force, const std::string& parts,
                               int threads) {
  require_valid(self, force, "build");
  const BuildOptions options{.parts = parts_of(parts), .threads = threads};
  py::gil_scoped_release free;
  return std::unique_ptr<PyModel>(
      new PyModel{.model = build_model(self.plan, options), .plan = self.plan});
}

/// The object with this id, as the dict of its entry in to_dict().
py::object object_dict(const PyPlan& self, const std::string& id) {
  const std::optional<ObjectRef> ref = find_object(self.plan, id);
  if (!ref) throw py::key_error(id);
  Plan alone;
  std::string list;
  visit_object(self.plan, *ref, [&](const auto& object) {
    for_each_list(alone, [&](auto& objects, ObjectKind kind) {
      if constexpr (std::is_same_v<typename std::decay_t<decltype(objects)>::value_type,
                                   std::decay_t<decltype(object)>>) {
        objects.push_back(object);
        list = list_name(kind);
      }
    });
  });
  return json_loads(write_plan_text(alone))[py::str(list)][py::int_(0)];
}

std::vector<std::string> ids(const PyPlan& self, const std::optional<std::string>& kind) {
  std::vector<std::string> out;
  for_each_list(self.plan, [&](const auto& objects, ObjectKind list) {
    for (std::size_t i = 0; i < objects.size(); ++i)
      if (!kind || *kind == kind_name(self.plan, ObjectRef{list, i})) out.push_back(objects[i].id);
  });
  return out;
}

/// Points the request at the sun at `time` (local at the plan's site.location), as
/// `roomcad render --sun` does.
void light_by_sun(const Plan& plan, const std::string& time, RenderRequest& request) {
  const Result<SunAt> sun =
      sun_at(site_location(plan, "sun"), plan.site.north.value_or(0.0), time, "sun");
  if (!sun) raise(sun.error());
  request.sun = sun->direction;
}

py::array_t<std::uint8_t> render(const PyPlan& self, RenderRequest request,
                                 const std::optional<std::string>& sun, bool force) {
  require_valid(self, force, "render");
  if (sun) light_by_sun(self.plan, *sun, request);
  Result<RenderOptions> asked = make_render_options(request, self.plan);
  if (!asked) raise(asked.error());
  const RenderOptions options = std::move(asked).value();
  FrameBuffers out;
  {
    py::gil_scoped_release free;
    const Model model =
        build_model(self.plan, BuildOptions{.parts = options.parts, .threads = request.threads});
    render_model(model, options, out, nullptr);
  }
  py::array_t<std::uint8_t> image({static_cast<py::ssize_t>(out.color.height),
                                   static_cast<py::ssize_t>(out.color.width), py::ssize_t{3}});
  std::copy(out.color.pixels.begin(), out.color.pixels.end(), image.mutable_data());
  return image;
}

std::string draw(const PyPlan& self, DrawRequest request, bool force) {
  require(check_draw_request(request));
  require_valid(self, force, "draw");
  request.title = self.name;
  std::optional<Result<SvgDocument>> document;
  {
    py::gil_scoped_release free;
    document.emplace(draw_plan_svg(self.plan, request));
  }
  return take(std::move(*document)).to_string();
}

using PlanClass = py::class_<PyPlan>;

/// Plan.load, from_json, from_dict, to_dict, to_json, save, validate.
void register_reading(PlanClass& plan) {
  plan.def_static("load", &load, py::arg("path"),
                  "Reads a plan file (JSON).\n"
                  "@raise roomcad.Error io_error (unreadable), parse_error or invalid_value\n"
                  "       (with .file, .line, .column) when it is not a plan")
      .def_static(
          "from_json", [](const std::string& text) { return read_text(text, "<json>", "plan"); },
          py::arg("text"), "Reads a plan from its JSON text. @raise roomcad.Error as load")
      .def_static(
          "from_dict",
          [](const py::dict& d) {
            // Compact, unchecked for cycles: the dict's text costs more than reading it.
            const std::string text =
                py::module_::import("json")
                    .attr("dumps")(d, py::arg("separators") = py::make_tuple(",", ":"),
                                   py::arg("check_circular") = false,
                                   py::arg("ensure_ascii") = false)
                    .cast<std::string>();
            return read_text(text, "<dict>", "plan");
          },
          py::arg("d"),
          "Reads a plan from a dict shaped like its JSON (as to_dict() gives).\n"
          "@raise roomcad.Error as load (.file is '<dict>')")
      .def(
          "to_dict", [](const PyPlan& self) { return json_loads(write_plan_text(self.plan)); },
          "The plan as a dict: the canonical JSON `roomcad fmt` writes, every field present.")
      .def(
          "to_json", [](const PyPlan& self) { return write_plan_text(self.plan); },
          "The canonical JSON text of the plan: the bytes `roomcad fmt` writes.")
      .def(
          "save",
          [](const PyPlan& self, const std::filesystem::path& path) {
            require(write_plan_file(self.plan, path));
          },
          py::arg("path"),
          "Writes the canonical JSON (as `roomcad fmt`), atomically: if anything\n"
          "fails the old file is left as it was. @raise roomcad.Error io_error")
      .def(
          "validate",
          [](const PyPlan& self, const std::string& rules) {
            const RuleSet set = take(load_rule_set(rules, "rules"));
            require(check_accessible_rooms(self.plan, set));
            PyReport out{check(self, set), {}, self.plan};
            out.format.ids = set.any_enabled();  // as `roomcad validate` prints it
            out.format.plan_file = self.file;
            return out;
          },
          py::arg("rules") = "default",
          "Checks the plan: every problem at once, exact for the numbers as written.\n"
          "@param rules  the rule set, as `roomcad validate --rules`: 'default' (the format's "
          "checks),\n"
          "              'accessibility', 'all', or the path of a rules file (JSON)\n"
          "@return a Report; report.to_dict() is what `roomcad validate --format json --rules "
          "RULES`\n"
          "        prints\n"
          "@raise roomcad.Error usage_error for an unknown set or a bad rules file (naming its "
          "field),\n"
          "       io_error for a file that cannot be read");
}

/// Plan.add, remove, move, rotate, scale, set: the edits of `roomcad add` ... `set`.
void register_edits(PlanClass& plan) {
  using About = std::optional<std::pair<double, double>>;
  plan.def(
          "add",
          [](PyPlan& self, const std::string& kind, const std::optional<std::string>& id,
             bool force, const py::kwargs& fields) {
            FieldValues values;
            for (const auto& [key, value] : fields) {
              const std::string name = py::str(key);
              values.emplace_back(name, field_value_text(value, name));
            }
            const EditSummary done = apply_edit(self, force, [&](Plan& plan) {
              return add_object(plan, kind, id.value_or(""), values);
            });
            return done.added.empty() ? std::string() : done.added.front();
          },
          py::arg("kind"), py::arg("id") = py::none(), py::kw_only(), py::arg("force") = false,
          "Adds a level, wall, door, window, slab, room (a name for a room), light or camera, as "
          "`roomcad add`.\n"
          "@param kind    'level', 'wall', 'door', 'window', 'slab', 'light' or 'camera'\n"
          "@param id      its id (default: generated, e.g. 'wall-3')\n"
          "@param fields  the object's fields by name (docs/plan-format.md): numbers in metres or\n"
          "               degrees, points (x, y), vectors (x, y, z), colours '#rrggbb', polygons\n"
          "               as lists of points, e.g. add('wall', **{'from': (0, 0)}, to=(4, 0))\n"
          "@param force   keep the edit even if it introduces plan errors\n"
          "@return the new object's id\n"
          "@raise roomcad.Error usage_error (unknown field, bad value), edit_refused")
      .def(
          "remove",
          [](PyPlan& self, const std::string& id, bool cascade, bool force) {
            apply_edit(self, force, [&](Plan& plan) {
              return remove_object(plan, id, RemoveOptions{.cascade = cascade});
            });
          },
          py::arg("id"), py::kw_only(), py::arg("cascade") = false, py::arg("force") = false,
          "Removes an object, as `roomcad rm`. @param cascade  also its openings (a wall) or its\n"
          "walls and slabs (a level). @raise roomcad.Error edit_refused when others depend on it")
      .def(
          "move",
          [](PyPlan& self, const std::string& id, double dx, double dy, bool force) {
            apply_edit(self, force, [&](Plan& plan) {
              return move_object(plan, id, Point2{dx, dy});
            });
          },
          py::arg("id"), py::arg("dx"), py::arg("dy"), py::kw_only(), py::arg("force") = false,
          "Moves a wall (with its openings) or a camera by (dx, dy) metres, as `roomcad move`.")
      .def(
          "rotate",
          [](PyPlan& self, const std::string& id, double degrees, const About& about, bool force) {
            apply_edit(self, force, [&](Plan& plan) {
              return rotate_object(plan, id, degrees, about_point(about));
            });
          },
          py::arg("id"), py::arg("degrees"), py::arg("about") = py::none(), py::kw_only(),
          py::arg("force") = false,
          "Turns an object counter-clockwise by `degrees` about the point `about` (x, y) "
          "(default:\n"
          "a wall's midpoint, a camera's target), as `roomcad rotate`; exact for quarter turns.")
      .def(
          "scale",
          [](PyPlan& self, const std::string& id, double factor, const About& about, bool force) {
            apply_edit(self, force, [&](Plan& plan) {
              return scale_object(plan, id, factor, about_point(about));
            });
          },
          py::arg("id"), py::arg("factor"), py::arg("about") = py::none(), py::kw_only(),
          py::arg("force") = false,
          "Scales an object by `factor` (> 0) about `about` (x, y), as `roomcad scale`.")
      .def(
          "set",
          [](PyPlan& self, const std::string& id, const std::string& field, const py::object& value,
             bool force) {
            const std::string text = field_value_text(value, field);
            apply_edit(self, force, [&](Plan& plan) { return set_field(plan, id, field, text); });
          },
          py::arg("id"), py::arg("field"), py::arg("value"), py::kw_only(),
          py::arg("force") = false,
          "Sets one field of an object ('site' for the site's), type-checked, as `roomcad set`.\n"
          "@raise roomcad.Error usage_error (unknown object or field, bad value), edit_refused")
      .def(
          "repair",
          [](PyPlan& self, double tolerance, const std::vector<std::string>& only) {
            RepairOptions options{.tolerance = tolerance, .only = {}};
            for (const std::string& name : only) {
              const std::optional<Code> code = parse_code(name);
              if (!code)
                require(Status::failure(Code::usage_error,
                                        fmt::format("only: '{}' is no validation code", name)));
              options.only.push_back(*code);
            }
            std::optional<Result<RepairResult>> repaired;
            {
              py::gil_scoped_release free;
              repaired.emplace(repair_plan(self.plan, options));
            }
            RepairResult r = take(std::move(*repaired));
            const py::object report = json_loads(format_repair_json(r));
            if (!r.edits.empty()) {
              self.plan = std::move(r.plan);
              self.reading.reset();
            }
            return report;
          },
          py::arg("tolerance") = 0.01, py::arg("only") = std::vector<std::string>{},
          "Repairs the plan in place, as `roomcad repair`: edits that clear its errors and move\n"
          "the built solid by at most `tolerance` metres (nothing where the union allows).\n"
          "@param only  the codes to repair (default: every code repair knows)\n"
          "@return the report as a dict, what `roomcad repair --format json` prints: 'edits'\n"
          "        (object, change, old, new, clears, moves), 'before' and 'after' (errors per\n"
          "        code), 'remaining' (each finding with its 'reason')\n"
          "@raise roomcad.Error invalid_value for a bad tolerance, usage_error for an unknown "
          "code");
}

/// plan[id], `id in plan`, ids(), import_warnings.
void register_objects(PlanClass& plan) {
  plan.def_property_readonly(
          "import_warnings", [](const PyPlan& self) { return self.import_warnings.items; },
          "What import_sweethome3d approximated or left out, as Findings (else empty)")
      .def("__getitem__", &object_dict, py::arg("id"),
           "The object with this id as a dict of its fields. @raise KeyError")
      .def("__contains__",
           [](const PyPlan& self, const std::string& id) {
             return find_object(self.plan, id).has_value();
           })
      .def("ids", &ids, py::arg("kind") = py::none(),
           "The ids of the plan's objects in file order, or of one kind ('wall', 'door', ...).");
}

/// Plan.build, render, draw, _repr_svg_, __repr__.
void register_pictures(PlanClass& plan) {
  plan.def("build", &build, py::arg("force") = false, py::arg("parts") = "all",
           py::arg("threads") = 0,
           "Builds the 3D model, as `roomcad build`: exact walls with their openings cut, the\n"
           "floor and the fixtures. Releases the GIL.\n"
           "@param force    build even if validation finds errors\n"
           "@param parts    'all' or a list such as 'walls,floor' (walls, floor, fixtures)\n"
           "@param threads  worker threads, 0 for all cores (the same model at any count)\n"
           "@return a Model. @raise roomcad.Error (the first error's code, not_buildable)")
      .def(
          "render",
          [](const PyPlan& self, const std::optional<std::string>& camera, int width, int height,
             const std::optional<std::string>& view, const py::object& eye,
             const py::object& target, const py::object& up, const std::string& projection,
             double fov, double view_height, const std::string& shading, const std::string& shadows,
             int shadow_res, int ssaa, const std::string& background, bool grid,
             const std::string& parts, int threads, const std::optional<std::string>& sun,
             bool force) {
            RenderRequest r;
            r.camera = camera.value_or("");
            r.width = width, r.height = height, r.view = view.value_or("");
            r.eye = eye.is_none() ? "" : field_value_text(eye, "eye");
            r.target = target.is_none() ? "" : field_value_text(target, "target");
            r.up = field_value_text(up, "up");
            r.projection = projection, r.fov = fov, r.view_height = view_height;
            r.shading = shading, r.shadows = shadows, r.shadow_res = shadow_res, r.ssaa = ssaa;
            r.background = background, r.grid = grid ? "on" : "off";
            r.parts = parts == "all" ? kAllParts : parts, r.threads = threads;
            return render(self, r, sun, force);
          },
          py::arg("camera") = py::none(), py::arg("width") = 1280, py::arg("height") = 720,
          py::arg("view") = py::none(), py::arg("eye") = py::none(), py::arg("target") = py::none(),
          py::arg("up") = py::make_tuple(0, 0, 1), py::arg("projection") = "perspective",
          py::arg("fov") = 50.0, py::arg("view_height") = 10.0, py::arg("shading") = "phong",
          py::arg("shadows") = "pcf", py::arg("shadow_res") = 1024, py::arg("ssaa") = 1,
          py::arg("background") = "#ffffff", py::arg("grid") = true, py::arg("parts") = "all",
          py::arg("threads") = 0, py::arg("sun") = py::none(), py::arg("force") = false,
          "Renders the model on the CPU: an H x W x 3 uint8 array (sRGB), pixel for pixel what\n"
          "`roomcad render` writes with the same options (the same defaults). Releases the GIL.\n"
          "@param camera   a plan camera's id; else eye and target ((x, y, z) metres); else "
          "`view`\n"
          "@param view     front, back, left, right, top or iso (default iso)\n"
          "@param shading  unlit, flat, gouraud, phong; shadows: off, hard, pcf; ssaa: 1, 2, 4\n"
          "@param sun      a local time at the site ('2026-04-22T14:30'): lit by the sun and\n"
          "                the sky there, as `roomcad render --sun` (needs site.location)\n"
          "@raise roomcad.Error usage_error naming the option, or the plan's first error")
      .def(
          "draw",
          [](const PyPlan& self, const std::string& view, const std::optional<std::string>& scale,
             double cut_height, const std::string& hidden, const std::string& parts, bool force) {
            DrawRequest r;
            r.view = view, r.cut_height = cut_height, r.hidden = hidden;
            if (scale) r.scale = *scale;
            r.parts = parts == "all" ? kAllParts : parts;
            return draw(self, r, force);
          },
          py::arg("view") = "plan", py::arg("scale") = py::none(), py::arg("cut_height") = 1.0,
          py::arg("hidden") = "dashed", py::arg("parts") = "all", py::arg("force") = false,
          "A line drawing as SVG text, what `roomcad draw` writes.\n"
          "@param view        plan, north, south, east, west, iso or camera:ID\n"
          "@param scale       paper scale '1:N' (default 1:50)\n"
          "@param cut_height  metres: the floor plan's horizontal section\n"
          "@param hidden      hidden edges of views: dashed or off")
      .def("_repr_svg_",
           [](const PyPlan& self) -> py::object {
             try {
               return py::str(draw(self, DrawRequest{}, true));
             } catch (const std::exception&) {
               return py::none();  // a plan that cannot be drawn shows as its repr
             }
           })
      .def("__repr__", [](const PyPlan& self) {
        return fmt::format("<Plan {}: {} walls, {} openings>", self.name, self.plan.walls.size(),
                           self.plan.openings.size());
      });
}

}  // namespace

void register_plan(py::module_& m) {
  PlanClass plan(m, "Plan",
                 "A room plan (docs/plan-format.md): read, validated, edited, built, rendered\n"
                 "and drawn by the same functions as the `roomcad` command.");
  register_reading(plan);
  register_edits(plan);
  register_objects(plan);
  register_pictures(plan);
  register_daylight(m, plan);
}

}  // namespace roomcad::python
