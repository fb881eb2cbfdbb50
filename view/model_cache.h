// SPDX-License-Identifier: GPL-3.0-or-later
// The window's model, rebuilt after an edit only where the edit touched it.
//
// The plan's walls are split into groups the build makes apart (view/wall_groups.h). Each
// group is built alone, with its openings, as the plan holding only them (build_model: its
// part of the wall solid and its door leaves and panes), and kept with that plan; the floor is
// built from the site alone. A later build reuses every group whose plan is equal (walls and
// openings, value for value, and the site and levels) and builds only the others, then joins
// the meshes, the groups in the order of their first walls, with the objects of the whole
// plan. So moving one wall of a house made of several separate buildings rebuilds that
// building; a change to lights or cameras rebuilds nothing.
//
// The result is build_model(plan)'s model up to the order of faces and vertices: the same
// faces (corners, object, kind, colour and normal), the same vertices and edges
// (tests/view/model_cache_test.cpp compares them after edits of many kinds).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "mesh/solid_mesh.h"
#include "plan/plan.h"
#include "solid/build_model.h"

namespace roomcad {

/// What the last ModelCache::build did.
struct ModelCacheStats {
  std::size_t groups = 0;   ///< wall groups of the plan
  std::size_t rebuilt = 0;  ///< of which built now (the others reused)
  bool floor_rebuilt = false;
};

class ModelCache {
 public:
  /// Builds the model of `plan`, reusing what the last build made for equal groups.
  /// @param[in] options  as build_model's; a change of path or parts since the last build
  ///                     rebuilds everything
  /// @return the model (see the header for how it equals build_model(plan, options))
  /// @throws PreconditionError as build_model does, naming the object; the cache then keeps
  ///         what it held.
  /// Cost: build_model of the changed groups, plus O(n log^2 n) grouping and O(faces) joining.
  [[nodiscard]] Model build(const Plan& plan, const BuildOptions& options);

  [[nodiscard]] const ModelCacheStats& last_stats() const { return stats_; }

 private:
  struct Entry {
    Plan plan;    ///< the group alone: its walls and openings, the site and levels
    Model model;  ///< build_model(plan) without the floor: walls and fixtures
  };
  /// @return the cached entry of the group plan `group` if equal, else one built now.
  std::shared_ptr<const Entry> find_or_build(Plan group, const BuildOptions& options);
  /// @return the floor of `site`, built now unless it is the last build's site.
  const SolidMesh& floor_of(const Site& site, const BuildOptions& options);

  /// The groups of the last build, by the id of their first wall (unique: wall_groups.h).
  std::unordered_map<std::string, std::shared_ptr<const Entry>> by_first_wall_;
  std::optional<Site> floor_site_;  ///< the site floor_ was built for
  SolidMesh floor_;
  std::optional<BuildOptions> options_;  ///< the options of the cached builds
  ModelCacheStats stats_;
};

}  // namespace roomcad
