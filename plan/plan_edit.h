// SPDX-License-Identifier: GPL-3.0-or-later
// Edits of a plan: add, remove, move, rotate, scale and set fields of its objects.
//
// Each function changes the plan in place and returns what it changed (for `--dry-run`), or
// throws PreconditionError (core/error.h) and leaves the plan as it was, when the
// edit cannot be expressed: an unknown id, a value of the wrong type, a wall with openings
// removed without cascade. Whether the edited plan is VALID is not judged here: the caller
// validates the result (validation/validate.h) and refuses edits that introduce errors.
//
// Geometry goes through plan/transform2d.h (homogeneous matrices, decimal-exact), so a
// move then the opposite move, or four quarter turns, give back the same numbers bit for bit
// under that header's 15-significant-digit condition.
//
// What a plan transform means (single objects and --all alike):
//  - positions in plan (wall ends, camera eye/target x and y, the site) go through the matrix;
//  - lengths measured along a wall (opening offset and width) scale with the plan, so openings
//    keep their place on a scaled wall; a moved or turned wall carries its openings unchanged;
//  - vertical sizes (heights, base, sill, z of cameras, view_height) and wall thickness are
//    kept: a scale is a change of the drawing, not of the building materials;
//  - directions (light direction, camera up) turn with a rotation and ignore moves and scales.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "plan/plan.h"

namespace roomcad {

/// What an edit did, by object id ("site" for the site), in the order the edit touched them.
struct EditSummary {
  std::vector<std::string> added;
  std::vector<std::string> removed;
  std::vector<std::string> changed;
  friend bool operator==(const EditSummary&, const EditSummary&) = default;
};

/// @return the kind of the object with this id: "level", "wall", "door", "window", "slab",
///         "light", "camera", or nullopt if no object has it. O(n).
[[nodiscard]] std::optional<std::string_view> object_kind(const Plan& plan, std::string_view id);

/// @return `<prefix>-N` with the smallest N >= 1 that no object of the plan uses. O(n) per try.
[[nodiscard]] std::string generate_id(const Plan& plan, std::string_view prefix);

/// @return an opening of this type with the spec's defaults (width, height, sill).
[[nodiscard]] Opening default_opening(OpeningType type);

/// Appends a wall. An empty `wall.id` becomes `wall-N` (generate_id).
/// @throws PreconditionError if the id is already used.
EditSummary add_wall(Plan& plan, Wall wall);

/// Appends an opening (`door-N` / `window-N` when the id is empty).
/// @throws PreconditionError if the id is used or `opening.wall` names no wall of the plan.
EditSummary add_opening(Plan& plan, Opening opening);

/// Appends a level (`level-N` when the id is empty). @throws PreconditionError on a used id.
EditSummary add_level(Plan& plan, Level level);

/// Appends a slab (`slab-N` when the id is empty).
/// @throws PreconditionError if the id is used or `slab.level` names no level of the plan.
EditSummary add_slab(Plan& plan, Slab slab);

/// Appends a room's name (`room-N` when the id is empty).
/// @throws PreconditionError if the id is used or `room.level` names no level of the plan.
EditSummary add_room(Plan& plan, RoomLabel room);

/// Appends a neighbouring building or tree (`obstruction-N` when the id is empty).
/// @throws PreconditionError if the id is used.
EditSummary add_obstruction(Plan& plan, Obstruction obstruction);

/// Appends a light (`light-N` when the id is empty). @throws PreconditionError on a used id.
EditSummary add_light(Plan& plan, Light light);

/// Appends a camera (`camera-N` when the id is empty). @throws PreconditionError on a used id.
EditSummary add_camera(Plan& plan, Camera camera);

struct RemoveOptions {
  bool cascade = false;  ///< removing a wall (a level) also removes its openings (its walls,
                         ///< their openings and its slabs)
};

/// @return the ids of the objects that depend on object `id` and go with it under cascade: a
///         wall's openings; a level's walls, their openings and its slabs. O(n).
[[nodiscard]] std::vector<std::string> dependent_objects(const Plan& plan, std::string_view id);

/// Removes the object with this id.
/// @throws PreconditionError if there is none; with Code::edit_refused if others depend on it
///         (dependent_objects) and not cascade.
EditSummary remove_object(Plan& plan, std::string_view id, const RemoveOptions& options = {});

/// Moves an object by `by` metres: a wall (its openings ride along), a camera (eye and target).
/// @throws PreconditionError for an unknown id, an opening (use slide_opening) or a light
///         (directional: it has no position).
EditSummary move_object(Plan& plan, std::string_view id, Point2 by);

/// Moves an opening along its wall by `du` metres (towards the wall's `to` end when positive).
/// @throws PreconditionError if `id` is not an opening.
EditSummary slide_opening(Plan& plan, std::string_view id, double du);

/// Turns an object counter-clockwise by `degrees` about `about` (default: a wall's midpoint,
/// a camera's target). A light's direction turns (a directional light has no position).
/// @throws PreconditionError for an unknown id, an opening (it turns with its wall) or a
///         non-finite angle.
EditSummary rotate_object(Plan& plan, std::string_view id, double degrees,
                          std::optional<Point2> about = std::nullopt);

/// Scales an object by `factor` about `about` (default as rotate_object): a wall's ends and its
/// openings' offsets and widths, a camera's eye and target. See the file comment.
/// @pre factor > 0 and finite. @throws PreconditionError if not, or for an opening or light.
EditSummary scale_object(Plan& plan, std::string_view id, double factor,
                         std::optional<Point2> about = std::nullopt);

/// Moves the whole plan, site included (so a moved plan stays inside its site).
EditSummary move_all(Plan& plan, Point2 by);

/// Turns the whole plan about `about` (default: the centre of the site). A quarter turn turns
/// the site too (its rectangle stays axis-aligned: origin moves, cells swap); any other angle
/// leaves the site where it is, so the result may lie outside it.
EditSummary rotate_all(Plan& plan, double degrees, std::optional<Point2> about = std::nullopt);

/// Scales the whole plan about `about` (default: the site's centre), site origin and
/// cell_size included. @pre factor > 0 and finite, else PreconditionError.
EditSummary scale_all(Plan& plan, double factor, std::optional<Point2> about = std::nullopt);

/// Sets one field of one object from text, type-checked: numbers (`2.5`), points (`1,2`),
/// vectors (`0,0,1`), colours (`#aabbcc`), enum names (`door`, `left`, `orthographic`) and
/// ids. `id` may also be "site" (when no object has that id) for the site's fields. Renaming
/// a wall renames its openings' references too.
/// @param[in] verb  the command named in error messages ("set", or "add" when building a
///                   new object field by field)
/// @return what changed, or the error naming the object, key and value (the plan unchanged),
///         e.g. `set: wall 'w1' has no field 'colour' (did you mean 'color'?)` (usage_error),
///         an unknown id or a used one (precondition). Never throws for its input.
[[nodiscard]] Result<EditSummary> set_field(Plan& plan, std::string_view id, std::string_view key,
                                            std::string_view value, std::string_view verb = "set");

/// Runs an edit of `plan` (a callable taking Plan& and returning what it changed or its
/// Error), whether it returns its Error or throws it as PreconditionError (the typed edits
/// above do, for their preconditions): the one place front ends turn both into a Result.
template <class Edit>
[[nodiscard]] Result<EditSummary> make_edit(Edit&& edit, Plan& plan) {
  try {
    return edit(plan);
  } catch (const PreconditionError& e) {
    return e.error();
  }
}

/// @return the ids of the objects that differ between two versions of a plan that hold the
///         same objects in the same order ("site" first if the site differs), as an
///         EditSummary's `changed`. @pre same numbers of walls, openings, lights, cameras.
[[nodiscard]] EditSummary changed_objects(const Plan& before, const Plan& after);

/// @return the names of the fields set_field accepts for an object kind ("level", "wall",
///         "door", "window", "slab", "light", "camera", "site"), in file order (the field
///         tables of plan/plan_fields.h).
[[nodiscard]] std::vector<std::string_view> field_names(std::string_view kind);

}  // namespace roomcad
