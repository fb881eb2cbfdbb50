// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad build PLAN -o OUT [--parts ...] [--boolean auto|general|nef] [--check] [--force]
// [--threads N] [--stats] [--format text|json] [--level ID]`: the plan's 3D model, exported
// (OBJ, OFF, PLY, STL, glTF, IFC) and checked.
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "io/gltf_export.h"
#include "io/ifc_export.h"
#include "io/mesh_export.h"
#include "io/wall_check_format.h"
#include "plan/plan_levels.h"
#include "solid/build_model.h"
#include "solid/wall_check.h"

namespace roomcad::cli {
namespace {

struct BuildCommandOptions {
  std::string plan;
  std::string out;
  std::string parts = kAllParts;
  std::string boolean = "auto";
  std::string format = "text";
  std::string level;  ///< empty: every level
  int threads = 0;
  bool check = false;
  bool force = false;
  bool verbose = false;  ///< list the plan's findings (else one line counts them)
  bool stats = false;
};

BooleanPath parse_boolean_path(const std::string& name) {
  if (name == "general") return BooleanPath::general;
  if (name == "nef" || name == "cgal") return BooleanPath::nef;
  return BooleanPath::automatic;
}

void print_stats(const Model& model, const BuildStats& stats) {
  std::fprintf(
      stderr,
      "build: %zu walls on the fast path, %zu on the general path, %zu on the Nef path, %.3f ms\n"
      "  walls %zu faces, floor %zu faces, fixtures %zu faces\n",
      stats.fast_path_walls, stats.general_path_walls, stats.nef_path_walls, stats.build_ms,
      model.walls.n_faces(), model.floor.n_faces(), model.fixtures.n_faces());
}

/// What -o writes: a mesh file, an IFC model (no mesh needed) or a glTF scene.
enum class OutputKind { none, mesh, ifc, gltf };

Result<OutputKind> output_kind(const std::string& out) {
  if (out.empty()) return OutputKind::none;
  std::string extension = std::filesystem::path(out).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".ifc") return OutputKind::ifc;
  if (extension == ".glb" || extension == ".gltf") return OutputKind::gltf;
  if (const auto format = mesh_format_of(out); !format)
    return Error{format.error().code, format.error().message + ", .ifc, .glb or .gltf"};
  return OutputKind::mesh;
}

/// Writes the plan as IFC and prints what was written.
int export_ifc(const Plan& plan, const std::string& out) {
  IfcExportSummary summary;
  if (const Status written = write_ifc_file(out, plan, &summary); !written)
    return report_failure("build", written.error());
  std::fprintf(stderr,
               "roomcad build: wrote %s: %zu storeys, %zu walls, %zu openings (%zu doors, %zu "
               "windows), %zu slabs, %zu spaces\n",
               out.c_str(), summary.storeys, summary.walls, summary.openings, summary.doors,
               summary.windows, summary.slabs, summary.spaces);
  return kExitOk;
}

int run_build(const BuildCommandOptions& options) {
  BuildOptions build;
  const Result<Parts> parts = parse_parts(options.parts);
  if (!parts) return report_failure("build", parts.error());
  build.parts = parts.value();
  const Result<OutputKind> kind = output_kind(options.out);
  if (!kind) return report_failure("build", kind.error());
  // The validation gate: errors stop the build unless --force.
  const Result<LoadedPlan> loaded =
      load_valid_plan("build", options.plan, options.force, findings_for(options.verbose));
  if (!loaded) return exit_status_of(loaded.code());
  const Result<Plan> level = select_level(loaded->plan, options.level);
  if (!level) return report_failure("build", level.error());
  const Plan& plan = level.value();
  if (kind.value() == OutputKind::ifc) {
    if (const int status = export_ifc(plan, options.out); status != kExitOk || !options.check)
      return status;
  }
  build.boolean = parse_boolean_path(options.boolean);
  build.threads = options.threads;
  const bool export_walls = build.parts.walls;
  if (options.check) build.parts.walls = true;  // checked even when not written
  BuildStats stats;
  Model model = build_model(plan, build, &stats);  // PreconditionError: main reports it
  if (options.stats) print_stats(model, stats);
  const bool meshed = kind.value() == OutputKind::gltf || kind.value() == OutputKind::mesh;
  if (meshed && !export_walls) model.walls = SolidMesh{}, add_face_properties(model.walls);
  if (kind.value() == OutputKind::gltf) {
    if (const Status written = write_gltf_file(options.out, model, plan); !written)
      return report_failure("build", written.error());
  } else if (kind.value() == OutputKind::mesh) {
    const MeshParts mesh{{&model.walls, &model.floor, &model.fixtures}, &model.objects};
    if (const Status written = write_mesh_file(options.out, mesh); !written)
      return report_failure("build", written.error());
  }
  if (!options.check) return kExitOk;
  const WallCheck verdict = check_walls(model, plan);
  std::fputs(
      (options.format == "json" ? format_wall_check_json(verdict) : format_wall_check_text(verdict))
          .c_str(),
      stdout);
  return verdict.ok ? kExitOk : kExitPlanErrors;
}

}  // namespace

void add_build_command(CLI::App& root, Commands& commands) {
  auto options = std::make_shared<BuildCommandOptions>();
  CLI::App* app = root.add_subcommand(
      "build",
      "Build the plan's 3D model: the wall solid (walls joined, every opening cut through),\n"
      "the tiled floor and the fixtures (door leaves, window panes), and write it to OUT in the\n"
      "format of its extension: .obj (+ .mtl beside it, one group per object, one material per\n"
      "colour), .off (face colours), .ply (ASCII, double coordinates, face colours), .stl\n"
      "(binary, float32 by the format), .glb or .gltf (+ .bin; glTF 2.0, one node per object,\n"
      "float32 by the format) or .ifc (IFC4: storeys, walls, openings with their doors and\n"
      "windows, slabs and spaces, written from the plan without meshing). Coordinates are\n"
      "written so they read back to the same doubles (except STL and glTF). The plan is\n"
      "validated first: errors stop the build unless --force.");
  app->add_option("PLAN", options->plan, "the plan file (JSON)")->required()->type_name("FILE");
  app->add_option("-o,--output", options->out,
                  "the file to write (.obj .off .ply .stl .glb .gltf .ifc)")
      ->type_name("OUT");
  app->add_option("--parts", options->parts,
                  "what to build and write: any of walls,slabs,floor,fixtures (walls,slabs: the "
                  "building's solid)")
      ->capture_default_str();
  app->add_option("--boolean", options->boolean,
                  "auto: the exact fast path where no boolean is needed, else the exact general\n"
                  "path (plane by plane); general: the general path for every wall; nef: CGAL's\n"
                  "exact Nef polyhedra for every wall, the reference to compare with (cgal: the\n"
                  "same, its old name)")
      ->check(CLI::IsMember({"auto", "general", "nef", "cgal"}))
      ->capture_default_str();
  app->add_flag(
      "--check", options->check,
      "check the wall solid as written (closed, 2-manifold, no self-intersection or\n"
      "degenerate face, outward, genus) and its volume against the plan's analytic volume\n"
      "(relative difference at most 1e-9, plus the surface area times an ulp of the largest\n"
      "coordinate, which rounding the vertices to doubles allows); exit 1 if any check fails. It "
      "checks the\n"
      "doubles that .obj, .off and .ply store exactly (.stl rounds them to float32)");
  add_format_option(*app, options->format, "format of the --check report");
  app->add_flag("--force", options->force, "build even if the plan has validation errors");
  add_verbose_flag(*app, options->verbose);
  app->add_option("--level", options->level,
                  "build only the walls of this level (and their openings), where they stand")
      ->type_name("ID");
  app->add_option("--threads", options->threads, "worker threads, 0 for all cores (same output)")
      ->check(CLI::Range(0, 256))  // as render/renderer.h kMaxThreads: no thread storm
      ->capture_default_str();
  app->add_flag("--stats", options->stats, "print paths taken, time and face counts to stderr");
  app->footer(
      "Exit status: 0 built (and checked); 1 PLAN has errors, cannot be built, or --check failed;\n"
      "2 could not run (bad arguments, unreadable PLAN, OUT not writable).\n"
      "Examples:\n"
      "  roomcad build examples/house.json -o house.obj\n"
      "  roomcad build examples/house.json -o house.ifc\n"
      "  roomcad build examples/house.json -o house.glb\n"
      "  roomcad build examples/house.json --parts walls --check -o walls.ply");
  app->callback([app] {
    if (app->count("-o") == 0 && app->count("--check") == 0)
      throw CLI::ValidationError("build", "give -o OUT, --check, or both");
  });
  commands.push_back({app, [options] { return run_build(*options); }});
}

}  // namespace roomcad::cli
