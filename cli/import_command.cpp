// SPDX-License-Identifier: GPL-3.0-or-later
// `roomcad import HOME.xml|HOME.sh3d|MODEL.ifc -o PLAN.json`: a Sweet Home 3D home or an IFC
// model as a plan.
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "cli/plan_loading.h"
#include "import/ifc_import.h"
#include "import/sweethome3d_import.h"
#include "io/plan_json.h"
#include "repair/repair.h"
#include "repair/repair_report.h"

namespace roomcad::cli {
namespace {

struct ImportArgs {
  std::string home;
  std::string output;
  std::string level;  ///< empty: every level
  bool ceilings = false;
  std::optional<double> chord_tolerance;  ///< unset: the format's default
  double wait_seconds = 0.0;              ///< --wait: for an editor of the plan being replaced
  bool repair = false;                    ///< --repair: repair the plan before writing it
  double tolerance = 0.01;                ///< --tolerance of the repair
};

/// With --repair: the plan repaired (repair/repair.h), its summary on stderr.
Result<Plan> repaired_if_asked(const ImportArgs& args, Plan plan) {
  if (!args.repair) return plan;
  Result<RepairResult> repaired = repair_plan(plan, {.tolerance = args.tolerance, .only = {}});
  if (!repaired) return repaired.error();
  fmt::print(stderr,
             "roomcad import: repair: {} (`roomcad repair PLAN --dry-run` lists what is left)\n",
             format_repair_summary(*repaired));
  return std::move(repaired->plan);
}

void print_warnings(const Report& warnings) {
  for (const Diagnostic& d : warnings.items)
    fmt::print(stderr, "roomcad import: warning [{}]: {}\n", to_string(d.code), d.message);
}

/// @return true for a file named .ifc or starting as a STEP file does.
bool is_ifc_file(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".ifc") return true;
  std::ifstream in(path, std::ios::binary);
  std::string head(64, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return is_step_text(head);
}

int run_ifc_import(const ImportArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const Result<IfcImport> imported = import_ifc_file(args.home);
  if (!imported) {
    report_failure("import", imported.error());
    return kExitCannotRun;  // a model that cannot be read is not a plan with errors: no plan yet
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const IfcImport& r = imported.value();
  print_warnings(r.warnings);
  const Result<Plan> plan = repaired_if_asked(args, r.plan);
  if (!plan) return report_failure("import", plan.error());
  if (const Status written = write_plan_file(*plan, args.output); !written)
    return report_failure("import", written.error());
  fmt::print(
      stderr,
      "roomcad import: {} ({}): {} of {} walls, {} of {} openings, {} of {} slabs read ({} walls, "
      "{} openings, {} slabs and {} levels in the plan); {} other elements skipped; {} warnings; "
      "{:.0f} ms; written to {}\n",
      args.home, r.schema, r.walls_read, r.source_walls, r.openings_read, r.source_openings,
      r.slabs_read, r.source_slabs, r.plan.walls.size(), r.plan.openings.size(),
      r.plan.slabs.size(), r.storeys, r.skipped, r.warnings.items.size(), ms, args.output);
  for (const std::string& line : format_tally(r))
    fmt::print(stderr, "roomcad import:   {}\n", line);
  return kExitOk;
}

int run_import(const ImportArgs& args) {
  if (is_ifc_file(args.home)) return run_ifc_import(args);
  Sh3dImportOptions options;
  if (!args.level.empty()) options.level = args.level;
  options.chord_tolerance = args.chord_tolerance;
  options.ceilings = args.ceilings;
  const Result<Sh3dImport> imported = import_sweethome3d_file(args.home, options);
  if (!imported) {
    report_failure("import", imported.error());
    return kExitCannotRun;  // a home that cannot be read is not a plan with errors: no plan yet
  }
  print_warnings(imported.value().warnings);
  const Result<Plan> repaired = repaired_if_asked(args, imported.value().plan);
  if (!repaired) return report_failure("import", repaired.error());
  const Plan& plan = *repaired;
  // Replaced under the plan's lock (io/plan_lock.h): an edit of the old plan under way would
  // otherwise rename its result over the imported plan just written, and the import be lost.
  const Result<PlanLock> lock = lock_plan("import", args.output, args.wait_seconds);
  if (!lock) return exit_status_of(lock.code());
  if (const Status written = write_plan_file(plan, args.output); !written)
    return report_failure("import", written.error());
  fmt::print(
      stderr,
      "roomcad import: {} levels, {} walls, {} openings and {} slabs from {} written to {}\n",
      plan.levels.size(), plan.walls.size(), plan.openings.size(), plan.slabs.size(), args.home,
      args.output);
  return kExitOk;
}

}  // namespace

void add_import_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* app = root.add_subcommand(
      "import",
      "Import a Sweet Home 3D home (its Home.xml, or a .sh3d file) or an IFC model (.ifc, IFC2X3 "
      "or IFC4: storeys, walls, openings with their doors and windows, slabs) as a plan. A Sweet "
      "Home 3D home comes with its levels, walls (sloped and curved as drawn), doors and windows "
      "(with their cut-out shapes) and rooms (floor slabs; ceilings with --ceilings). What cannot "
      "be represented (doors and windows that fit no wall, walls of no length, IFC bodies that "
      "are not extrusions) and elements left out are reported as warnings naming the wall, item "
      "or entity (\"#1234 IFCCURTAINWALL\").");
  app->add_option("home", args->home, "Sweet Home 3D Home.xml or .sh3d file, or an .ifc file")
      ->required();
  app->add_option("-o,--output", args->output, "plan JSON file to write")->required();
  app->add_option("--level", args->level, "import only the level with this name");
  app->add_flag("--ceilings", args->ceilings,
                "Also import the rooms' ceilings as slabs where no floor above covers them "
                "(closes the top storey; Sweet Home 3D shows ceilings from below only)");
  app->add_option("--chord-tolerance", args->chord_tolerance,
                  "site.chord_tolerance of the plan: largest distance in metres between a curved "
                  "wall and its chords (default 0.001, the format's, left unwritten)")
      ->check(CLI::PositiveNumber);
  app->add_flag("--repair", args->repair,
                "repair the plan before writing it, as `roomcad repair` does (walls drawn twice or "
                "into their neighbours, openings a hair past their wall, ...)");
  app->add_option("--tolerance", args->tolerance,
                  "with --repair: how far, in metres, the built solid may move")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_wait_option(*app, args->wait_seconds,
                  "seconds to wait for another editor of the plan being replaced (an edit "
                  "command, `roomcad view` saving) to finish before giving up (exit 2)");
  commands.push_back({app, [args] { return run_import(*args); }});
}

}  // namespace roomcad::cli
