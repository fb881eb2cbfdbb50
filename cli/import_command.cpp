// `roomcad import HOME.xml|HOME.sh3d -o PLAN.json`: a Sweet Home 3D home as a plan.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.h"
#include "io/plan_json.h"
#include "import/sweethome3d_import.h"

namespace roomcad::cli {
namespace {

struct ImportArgs {
  std::string home;
  std::string output;
  std::string level;  ///< empty: every level
  double chord_tolerance = 0.01;
};

int run_import(const ImportArgs& args) {
  Sh3dImportOptions options;
  if (!args.level.empty()) options.level = args.level;
  options.chord_tolerance = args.chord_tolerance;
  const Result<Sh3dImport> imported = import_sweethome3d_file(args.home, options);
  if (!imported) {
    report_failure("import", imported.error());
    return kExitCannotRun;  // a home that cannot be read is not a plan with errors: no plan yet
  }
  for (const Diagnostic& d : imported.value().warnings.items)
    fmt::print(stderr, "roomcad import: warning [{}]: {}\n", to_string(d.code), d.message);
  const Plan& plan = imported.value().plan;
  if (const Status written = write_plan_file(plan, args.output); !written)
    return report_failure("import", written.error());
  fmt::print(stderr, "roomcad import: {} walls and {} openings from {} written to {}\n",
             plan.walls.size(), plan.openings.size(), args.home, args.output);
  return kExitOk;
}

}  // namespace

void add_import_command(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* app = root.add_subcommand(
      "import",
      "Import a Sweet Home 3D home (its Home.xml, or a .sh3d file) as a plan. Approximations "
      "(curved and sloped walls, round cut-outs, doors and windows that fit no wall) are "
      "reported as warnings naming the wall or item.");
  app->add_option("home", args->home, "Sweet Home 3D Home.xml or .sh3d file")->required();
  app->add_option("-o,--output", args->output, "plan JSON file to write")->required();
  app->add_option("--level", args->level, "import only the level with this name");
  app->add_option("--chord-tolerance", args->chord_tolerance,
                  "largest distance in metres between a curved wall and its straight pieces")
      ->check(CLI::PositiveNumber);
  commands.push_back({app, [args] { return run_import(*args); }});
}

}  // namespace roomcad::cli
