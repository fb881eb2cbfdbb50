// Building the 3D model of a plan: the wall solid (walls joined, openings cut), the tiled
// floor and the fixtures, as OpenMesh meshes (modeling/solid_mesh.h).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "modeling/plan.h"
#include "modeling/solid_mesh.h"

namespace roomcad {

/// Thrown by modeling when a documented precondition does not hold; the message names the
/// function, the object id, the failed check and the values (STYLE rule 6).
class PreconditionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Which parts of the model to build.
struct Parts {
  bool walls = true;
  bool floor = true;
  bool fixtures = true;
};

enum class BooleanPath {
  automatic,  ///< per wall: the exact fast path where no general boolean is needed, else CGAL
  cgal,       ///< CGAL's exact booleans everywhere (to compare against the fast path)
};

struct BuildOptions {
  BooleanPath boolean = BooleanPath::automatic;
  Parts parts;
  int threads = 0;  ///< 0: all cores; output is identical at any thread count
};

/// What a build did, for --stats, benchmarks and tests.
struct BuildStats {
  std::size_t fast_path_walls = 0;
  std::size_t cgal_path_walls = 0;
  double build_ms = 0.0;
};

/// Builds the model of a plan.
/// @pre validate(plan).ok() (validation/validate.h); a plan with errors may still be built
///      (`--force`), but an opening that cannot be cut throws instead of leaving a wall whole.
/// @throws PreconditionError naming the object that could not be built. Never a silent
///         missing hole.
[[nodiscard]] Model build_model(const Plan& plan, const BuildOptions& options = {},
                                BuildStats* stats = nullptr);

}  // namespace roomcad
