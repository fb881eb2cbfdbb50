// SPDX-License-Identifier: GPL-3.0-or-later
// The rounds of repair: validate, propose one edit set per finding (repair/detail/*), apply
// those that touch distinct objects, keep those that clear their finding, add none and, where
// they claim to keep the union, leave the analytic volume as it was; until a round keeps none.
#include "repair/repair.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "geometry/joins.h"
#include "repair/detail/context.h"
#include "repair/detail/openings.h"
#include "repair/detail/proposal.h"
#include "repair/detail/slabs.h"
#include "repair/detail/wall_overlaps.h"
#include "solid/analytic_volume.h"
#include "validation/validate.h"

namespace roomcad {

std::string_view to_string(RepairChange change) {
  switch (change) {
    case RepairChange::merge: return "merge";
    case RepairChange::trim: return "trim";
    case RepairChange::extend: return "extend";
    case RepairChange::snap: return "snap";
    case RepairChange::cut: return "cut";
    case RepairChange::move: return "move";
    case RepairChange::shorten: return "shorten";
    case RepairChange::remove: break;
  }
  return "delete";
}

namespace {

using detail::Attempt;
using detail::Proposal;

/// Rounds stop earlier when one keeps nothing; a wall overlapping many others takes a round
/// per neighbour it is trimmed against, so the bound is generous.
constexpr int kMostRounds = 64;
/// Passes of rounds (repair_plan): the last of them edits nothing, in practice the second.
constexpr int kMostPasses = 8;

std::vector<Diagnostic> errors_of(const Plan& plan) {
  Report report = validate(plan, {.room_warnings = false, .unknown_field_warnings = false});
  std::vector<Diagnostic> errors;
  for (Diagnostic& d : report.items)
    if (d.severity == Severity::error) errors.push_back(std::move(d));
  return errors;
}

std::map<Code, std::size_t> counts_of(const std::vector<Diagnostic>& errors) {
  std::map<Code, std::size_t> counts;
  for (const Diagnostic& d : errors) ++counts[d.code];
  return counts;
}

Attempt propose(const detail::RepairContext& ctx, const Diagnostic& finding) {
  switch (finding.code) {
    case Code::wall_overlap: return detail::propose_wall_overlap(ctx, finding);
    case Code::slab_overlap: return detail::propose_slab_cut(ctx, finding);
    case Code::opening_outside_wall:
    case Code::opening_overlap:
    case Code::opening_blocked: return detail::propose_opening_fix(ctx, finding);
    default: break;
  }
  return detail::refused("no edit of this kind clears it");
}

std::optional<double> volume_of(const Plan& plan) {
  try {
    return analytic_wall_volume(plan);
  } catch (const PreconditionError&) {
    return std::nullopt;  // a plan that does not build: the claims cannot be checked
  }
}

/// The analytic volume of the plan being repaired, computed when a round first needs it (a
/// plan with nothing to repair costs one validation, no volume) and again after edits that
/// move the solid.
class PlanVolume {
 public:
  const std::optional<double>& of(const Plan& plan) {
    if (!known_) value_ = volume_of(plan), known_ = true;
    return value_;
  }
  void forget() { known_ = false; }

 private:
  std::optional<double> value_;
  bool known_ = false;
};

Plan applied(Plan plan, const std::vector<const Proposal*>& proposals) {
  for (const Proposal* p : proposals)
    for (const RepairEdit& e : p->edits) detail::apply_edit(plan, e);
  return plan;
}

/// Splits `proposals` into those that hold and those that do not: applied to `plan` with every
/// proposal held before them, they change its volume by no more than their slack (exactly
/// nothing for those that claim to keep the union). By halving: one volume when all hold, and
/// each half is tried on top of what held before it, so that proposals which hold alone but
/// not together (removing the last of three walls drawn over one corner turns its union into
/// a mitre) are caught.
void check_volumes(const Plan& plan, double volume, const std::vector<const Proposal*>& proposals,
                   std::vector<const Proposal*>& hold, std::vector<const Proposal*>& fail) {
  if (proposals.empty()) return;
  std::vector<const Proposal*> all = hold;
  all.insert(all.end(), proposals.begin(), proposals.end());
  double slack = 0;
  for (const Proposal* p : all) slack += detail::volume_slack(plan, *p);
  const std::optional<double> changed = volume_of(applied(plan, all));
  if (changed && std::fabs(*changed - volume) <= slack) {
    hold = std::move(all);
    return;
  }
  if (proposals.size() == 1) {
    fail.push_back(proposals[0]);
    return;
  }
  const auto mid = proposals.begin() + static_cast<std::ptrdiff_t>(proposals.size() / 2);
  check_volumes(plan, volume, {proposals.begin(), mid}, hold, fail);
  check_volumes(plan, volume, {mid, proposals.end()}, hold, fail);
}

std::set<std::string> objects_of(const Proposal& p) {
  std::set<std::string> ids(p.finding.objects.begin(), p.finding.objects.end());
  for (const RepairEdit& e : p.edits) ids.insert(e.object);
  return ids;
}

bool shares(const std::vector<std::string>& ids, const std::set<std::string>& set) {
  return std::any_of(ids.begin(), ids.end(),
                     [&](const std::string& id) { return set.contains(id); });
}

using JoinKey = std::tuple<std::string, std::string, JoinKind>;

/// The plan's joins by wall ids (lower id first).
std::set<JoinKey> joins_by_id(const Plan& plan) {
  std::set<JoinKey> out;
  for (const Join& j : find_joins(plan).pairs) {
    const auto [a, b] = std::minmax(plan.walls[j.a].id, plan.walls[j.b].id);
    out.emplace(a, b, j.kind);
  }
  return out;
}

/// @return the walls whose joins differ between `before` and `after` for a reason the
///         proposals do not give: a join that appears or goes, or changes kind (a mitre that
///         becomes a union), between walls no proposal joins on purpose (its finding's pair)
///         or removes. A moved end or a removed wall there changes the solid at a corner by
///         up to half a thickness, which no edit's `moves` counts.
std::set<std::string> walls_with_changed_joins(const std::set<JoinKey>& before,
                                               const std::set<JoinKey>& after,
                                               const std::vector<const Proposal*>& proposals) {
  std::set<std::pair<std::string, std::string>> meant;
  std::set<std::string> removed;
  for (const Proposal* p : proposals) {
    if (p->finding.objects.size() == 2)
      meant.insert(std::minmax(p->finding.objects[0], p->finding.objects[1]));
    for (const RepairEdit& e : p->edits)
      if (e.change == RepairChange::remove) removed.insert(e.object);
  }
  std::vector<JoinKey> changed;
  std::set_symmetric_difference(before.begin(), before.end(), after.begin(), after.end(),
                                std::back_inserter(changed));
  std::set<std::string> walls;
  for (const auto& [a, b, kind] : changed) {
    if (meant.contains({a, b}) || removed.contains(a) || removed.contains(b)) continue;
    walls.insert(a);
    walls.insert(b);
  }
  return walls;
}

/// The walls each wall is joined to (both ways).
std::map<std::string, std::set<std::string>> neighbours_of(const std::set<JoinKey>& joins) {
  std::map<std::string, std::set<std::string>> out;
  for (const auto& [a, b, kind] : joins) out[a].insert(b), out[b].insert(a);
  return out;
}

/// One round's bookkeeping across rounds: per finding, how many of its proposals failed, and
/// why the last did.
struct Tries {
  std::map<FindingKey, std::size_t> failed;
  std::map<FindingKey, std::string> reason;
  void fail(const FindingKey& key, std::string why) {
    ++failed[key];
    reason[key] = std::move(why);
  }
};

/// The round's proposals: per finding, the first not yet failed, if its edited objects are
/// touched by no other proposal of the round and it edits none that another reads.
std::vector<Proposal> choose(const Plan& plan, const RepairOptions& options,
                             const std::vector<Diagnostic>& errors, Tries& tries) {
  const detail::RepairContext ctx(plan, options.tolerance, errors);
  std::set<std::string> edited, read;
  std::vector<Proposal> chosen;
  for (const Diagnostic& d : errors) {
    if (!options.only.empty() &&
        std::find(options.only.begin(), options.only.end(), d.code) == options.only.end())
      continue;
    const FindingKey key = detail::key_of(d);
    Attempt attempt = propose(ctx, d);
    const std::size_t next = tries.failed[key];
    if (next >= attempt.proposals.size()) {
      if (next == 0 || !attempt.reason.empty()) tries.reason[key] = attempt.reason;
      continue;
    }
    Proposal p = std::move(attempt.proposals[next]);
    p.finding = key;
    std::set<std::string> edits;
    for (const RepairEdit& e : p.edits) edits.insert(e.object);
    const std::set<std::string> all = objects_of(p);
    const bool clash = std::any_of(all.begin(), all.end(), [&](const std::string& id) {
      return edited.contains(id) || (edits.contains(id) && read.contains(id));
    });
    if (clash) continue;  // waits for a later round
    edited.insert(edits.begin(), edits.end());
    read.insert(all.begin(), all.end());
    chosen.push_back(std::move(p));
  }
  return chosen;
}

/// Applies the proposals that hold to `plan` (and `errors` to its errors), and appends their
/// edits, with what they clear, to `made`. A proposal that does not hold is marked failed in
/// `tries`, so that the next round tries the finding's next one.
/// @return false when there was nothing to propose (the pass is over).
bool run_round(Plan& plan, std::vector<Diagnostic>& errors, PlanVolume& plan_volume,
               const RepairOptions& options, Tries& tries, std::vector<RepairEdit>& made) {
  std::vector<Proposal> chosen = choose(plan, options, errors, tries);
  if (chosen.empty()) return false;
  std::vector<const Proposal*> kept;
  for (const Proposal& p : chosen) kept.push_back(&p);
  const std::optional<double> volume = plan_volume.of(plan);
  if (!volume) {
    // A plan that does not build (an opening past its wall cannot be cut) has no volume to
    // check edits on: first the openings are fitted to their walls, whose moves are exact
    // (an edge of a hole moves by what the opening is shortened), then the rest is tried.
    std::vector<const Proposal*> fits;
    for (const Proposal* p : kept)
      if (p->finding.code == Code::opening_outside_wall) fits.push_back(p);
    if (fits.empty()) {
      for (const Proposal* p : kept)
        tries.fail(p->finding, "the plan cannot be built, so no edit of it can be checked");
      return true;
    }
    kept = std::move(fits);
  }
  // The proposals whose volume holds; run again on what the checks below leave.
  const auto volume_holds = [&](std::vector<const Proposal*> proposals) {
    if (!volume) return proposals;
    std::vector<const Proposal*> hold, fail;
    check_volumes(plan, *volume, proposals, hold, fail);
    for (const Proposal* p : fail)
      tries.fail(p->finding,
                 "the edit would change the solid by more than it moves (a join "
                 "of other walls changes with it)");
    return hold;
  };
  kept = volume_holds(std::move(kept));
  std::set<FindingKey> old_keys;
  for (const Diagnostic& d : errors) old_keys.insert(detail::key_of(d));
  // Drop what does not clear its finding or adds one on its objects, until all that is left
  // holds (each pass drops at least one, or ends).
  const std::set<JoinKey> joins_before = joins_by_id(plan);
  const auto neighbours = neighbours_of(joins_before);
  while (!kept.empty()) {
    Plan next = applied(plan, kept);
    std::vector<Diagnostic> next_errors = errors_of(next);
    std::set<FindingKey> new_keys;
    for (const Diagnostic& d : next_errors) new_keys.insert(detail::key_of(d));
    const std::set<std::string> rejoined =
        walls_with_changed_joins(joins_before, joins_by_id(next), kept);
    std::vector<const Proposal*> holding;
    for (const Proposal* p : kept) {
      const std::set<std::string> ids = objects_of(*p);
      // A proposal that moves a wall (by a snap, or a trim the other wall does not quite
      // cover) is blamed for a changed join of that wall, or of a wall joined to it (the third
      // wall at a corner whose mitre or union changes): the volume's slack for the move could
      // hide that change. What keeps the union exactly, the volume has checked.
      const bool rejoins = std::any_of(p->edits.begin(), p->edits.end(), [&](const RepairEdit& e) {
        const auto near = neighbours.find(e.object);
        if (e.moves == 0 || near == neighbours.end()) return false;
        return rejoined.contains(e.object) ||
               std::any_of(near->second.begin(), near->second.end(),
                           [&](const std::string& w) { return rejoined.contains(w); });
      });
      const auto added =
          std::find_if(next_errors.begin(), next_errors.end(), [&](const Diagnostic& d) {
            return !old_keys.contains(detail::key_of(d)) && shares(d.objects, ids);
          });
      if (new_keys.contains(p->finding))
        tries.fail(p->finding, "the edit that would clear it does not");
      else if (rejoins)
        tries.fail(p->finding, "the edit would change how other walls join at a corner");
      else if (added != next_errors.end())
        tries.fail(p->finding,
                   fmt::format("two repairs contradict each other: the edit would "
                               "cause a new {} on {}",
                               to_string(added->code), fmt::join(added->objects, ", ")));
      else holding.push_back(p);
    }
    if (holding.size() < kept.size()) {
      // What is left holds only together with what was dropped: check its volume again.
      kept = volume_holds(std::move(holding));
      continue;
    }
    for (const Proposal* p : kept) {
      const std::set<std::string> ids = objects_of(*p);
      std::vector<FindingKey> cleared;
      for (const Diagnostic& d : errors)
        if (!new_keys.contains(detail::key_of(d)) && shares(d.objects, ids))
          cleared.push_back(detail::key_of(d));
      for (RepairEdit e : p->edits) {
        e.clears = cleared;
        made.push_back(std::move(e));
      }
    }
    plan = std::move(next);
    errors = std::move(next_errors);
    return true;
  }
  return true;
}

bool moves_solid(const std::vector<RepairEdit>& edits, std::size_t from) {
  return std::any_of(edits.begin() + static_cast<std::ptrdiff_t>(from), edits.end(),
                     [](const RepairEdit& e) { return e.moves != 0; });
}

}  // namespace

Result<RepairResult> repair_plan(const Plan& input, const RepairOptions& options) {
  if (!(std::isfinite(options.tolerance) && options.tolerance >= 0))
    return Result<RepairResult>::failure(
        Code::invalid_value,
        fmt::format("the repair tolerance must be a finite number of metres >= 0, not {}",
                    options.tolerance));
  RepairResult result{input, options.tolerance, {}, {}, {}, {}};
  std::vector<Diagnostic> errors = errors_of(input);
  result.before = counts_of(errors);
  Tries tries;
  PlanVolume volume;
  // Passes of rounds until one edits nothing: a proposal that failed with others in its round
  // may hold on its own in the next pass, and the result is then one that repair leaves as it
  // is (repairing a repaired plan changes nothing).
  for (int pass = 0; pass < kMostPasses; ++pass) {
    const std::size_t pass_start = result.edits.size();
    tries = {};
    for (int round = 0; round < kMostRounds; ++round) {
      const std::size_t first = result.edits.size();
      if (!run_round(result.plan, errors, volume, options, tries, result.edits)) break;
      if (moves_solid(result.edits, first)) volume.forget();
    }
    if (result.edits.size() == pass_start) break;
  }
  result.after = counts_of(errors);
  for (Diagnostic& d : errors) {
    const auto reason = tries.reason.find(detail::key_of(d));
    std::string why = reason != tries.reason.end() && !reason->second.empty()
                          ? reason->second
                          : std::string("no edit of this kind clears it");
    result.remaining.push_back({std::move(d), std::move(why)});
  }
  return result;
}

}  // namespace roomcad
