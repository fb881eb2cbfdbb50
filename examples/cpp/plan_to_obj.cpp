// SPDX-License-Identifier: GPL-3.0-or-later
// plan_to_obj PLAN OUT.obj: reads a roomcad plan, validates it, builds its 3D model and writes
// it as OBJ, with roomcad as a library (find_package(roomcad) in CMakeLists.txt).
// Exit status as the roomcad command's: 0 written, 1 the plan has errors, 2 could not run.
#include <cstdio>
#include <exception>

#include "io/mesh_export.h"
#include "io/plan_json.h"
#include "solid/build_model.h"
#include "validation/report_format.h"
#include "validation/validate.h"

int main(int argc, char** argv) {
  using namespace roomcad;
  if (argc != 3) {
    std::fprintf(stderr, "usage: plan_to_obj PLAN OUT.obj\n");
    return kExitCannotRun;
  }
  // Reading: a file that is not a plan gives its problems, with lines and columns.
  Report report;
  Result<Plan> plan = read_plan_file(argv[1], &report);
  if (!plan) {
    std::fputs(format_report_text(report, false).c_str(), stderr);
    return exit_status_of(plan.code());
  }
  // Validation: every problem at once, each with a fix.
  report.append(validate(plan.value(), ValidateOptions{.unknown_field_warnings = false}));
  std::fputs(format_report_text(report, false).c_str(), stderr);
  if (!report.ok()) return kExitPlanErrors;
  try {
    // Modelling: exact walls with their openings cut, the floor and the fixtures.
    const Model model = build_model(plan.value());
    const MeshParts parts{{&model.walls, &model.floor, &model.fixtures}, &model.objects};
    if (const Status written = write_mesh_file(argv[2], parts); !written) {
      std::fprintf(stderr, "%s\n", written.error().message.c_str());
      return kExitCannotRun;
    }
    std::printf("%s: %zu wall faces, %zu floor faces, %zu fixture faces\n", argv[2],
                model.walls.n_faces(), model.floor.n_faces(), model.fixtures.n_faces());
  } catch (const PreconditionError& e) {  // a solid that cannot be built
    std::fprintf(stderr, "%s\n", e.what());
    return exit_status_of(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitCannotRun;
  }
  return kExitOk;
}
