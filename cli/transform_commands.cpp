// SPDX-License-Identifier: GPL-3.0-or-later
// roomcad move | rotate | scale PLAN (ID | --all) ...: the plan transforms of plan/plan_edit.h,
// through homogeneous matrices (plan/transform2d.h): quarter turns exact, moves and scales
// undone bit for bit for decimal coordinates of up to 15 significant digits. A move or quarter
// turn that its opposite would not undo exactly (longer numbers) says so on stderr.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>

#include "cli/command.h"
#include "cli/edit_session.h"
#include "plan/plan_edit.h"
#include "plan/transform2d.h"
#include "plan/value_text.h"

namespace roomcad::cli {
namespace {

struct TransformArgs {
  std::string path;
  std::string id;
  bool all = false;
  std::string amount;  ///< --by, --deg or --factor, as typed
  std::string about;   ///< --about x,y, empty when not given
  EditFlags flags;
};

/// A transform of the plan (sign +1), or its opposite (sign -1: a move by -d, a turn by -a).
using SignedEdit = std::function<EditSummary(Plan&, double sign)>;

/// Registers PLAN, ID, --all and the edit flags on a new transform subcommand.
CLI::App* add_transform(CLI::App& root, const std::string& name, const std::string& about,
                        const std::string& footer, TransformArgs& args) {
  CLI::App* app = root.add_subcommand(name, about);
  app->footer(footer +
              "\nThe edited plan is validated: an edit that introduces errors is refused (exit 1,\n"
              "file untouched) unless --force.");
  app->add_option("PLAN", args.path, "plan file to edit")->required();
  app->add_option("ID", args.id, "id of the object to transform");
  app->add_flag("--all", args.all,
                "transform the whole plan (site included) instead of one object");
  add_edit_flags(*app, args.flags);
  return app;
}

/// Warns when the opposite edit would not give `before` back bit for bit: the promise of
/// plan/transform2d.h holds for numbers of up to 15 significant digits, and a plan may hold
/// longer ones (computed corners), which the result cannot keep exactly.
void warn_unless_undoable(const std::string& name, const Plan& before, const Plan& after,
                          const SignedEdit& edit) {
  Plan back = after;
  edit(back, -1.0);
  const EditSummary off = changed_objects(before, back);
  if (off.changed.empty()) return;
  fmt::print(stderr,
             "roomcad {}: warning: the opposite {} would not restore {} bit for bit (numbers of "
             "more than 15 significant digits come back within an ulp or so)\n",
             name, name, fmt::join(off.changed, ", "));
}

/// Runs a transform of one object or (--all) of the plan; with `undoable`, checks that the
/// opposite transform would restore the plan exactly and warns if not.
int run_transform(const std::string& name, const TransformArgs& args, const SignedEdit& edit,
                  bool undoable) {
  if (args.all == !args.id.empty())
    return report_failure(
        name,
        Error{Code::usage_error, args.all ? "give an object ID or --all, not both"
                                          : "give the ID of the object to transform, or --all"});
  return run_edit(name, args.path, args.flags, [&](Plan& plan) {
    const Plan before = plan;
    EditSummary summary = edit(plan, 1.0);
    if (undoable) warn_unless_undoable(name, before, plan, edit);
    return summary;
  });
}

/// @return --about's centre (nullopt: none given), or its usage_error.
Result<std::optional<Point2>> optional_about(const TransformArgs& args) {
  if (args.about.empty()) return std::optional<Point2>{};
  const Result<Point2> about = point_option("--about", args.about);
  if (!about) return about.error();
  return std::optional<Point2>(*about);
}

void add_move(CLI::App& root, Commands& commands) {
  auto args = std::make_shared<TransformArgs>();
  CLI::App* app =
      add_transform(root, "move", "Move an object, or the whole plan, by a distance",
                    "Examples:\n"
                    "  roomcad move plan.json south --by 0.5,0      # a wall and its openings\n"
                    "  roomcad move plan.json win1 --by -0.25       # an opening along its wall\n"
                    "  roomcad move plan.json --all --by 2,-1\n",
                    *args);
  app->add_option("--by", args->amount,
                  "dx,dy in metres; for a door or window one number du, "
                  "along its wall")
      ->required();
  commands.push_back(
      {app, [args] {
         const auto by = parse_point2(args->amount);
         const auto du = parse_number(args->amount);
         if (!by && (!du || args->all))
           return report_failure(
               "move",
               Error{Code::usage_error,
                     fmt::format("--by wants dx,dy in metres{}, got '{}'",
                                 args->all ? ""
                                           : " (or one number du to move a door or window along "
                                             "its wall)",
                                 args->amount)});
         const auto move = [&](Plan& plan, double sign) {
           if (!by) return slide_opening(plan, args->id, sign * *du);
           const Point2 shift{sign * by->x, sign * by->y};
           return args->all ? move_all(plan, shift) : move_object(plan, args->id, shift);
         };
         return run_transform("move", *args, move, true);
       }});
}

/// rotate and scale: one number (--deg / --factor) and an optional centre (--about).
struct AboutCommand {
  std::string name;
  std::string description;
  std::string footer;
  std::string amount_option;  ///< "--deg" or "--factor"
  std::string amount_help;
  EditSummary (*one)(Plan&, std::string_view, double, std::optional<Point2>);
  EditSummary (*whole)(Plan&, double, std::optional<Point2>);
  bool (*undo_is_exact)(double amount);  ///< when the opposite amount restores the plan exactly
};

void add_about_command(CLI::App& root, Commands& commands, const AboutCommand& spec) {
  auto args = std::make_shared<TransformArgs>();
  CLI::App* app = add_transform(root, spec.name, spec.description, spec.footer, *args);
  app->add_option(spec.amount_option, args->amount, spec.amount_help)->required();
  app->add_option("--about", args->about,
                  "centre x,y in metres (default: a wall's midpoint, a "
                  "camera's target, the site's centre for --all)");
  commands.push_back({app, [args, spec] {
                        const Result<double> amount_given =
                            number_option(spec.amount_option, args->amount);
                        if (!amount_given) return report_failure(spec.name, amount_given.error());
                        const double amount = *amount_given;
                        const Result<std::optional<Point2>> about_given = optional_about(*args);
                        if (!about_given) return report_failure(spec.name, about_given.error());
                        const std::optional<Point2> about = *about_given;
                        const auto edit = [&](Plan& plan, double sign) {
                          return args->all ? spec.whole(plan, sign * amount, about)
                                           : spec.one(plan, args->id, sign * amount, about);
                        };
                        return run_transform(spec.name, *args, edit, spec.undo_is_exact(amount));
                      }});
}

}  // namespace

void add_transform_commands(CLI::App& root, Commands& commands) {
  add_move(root, commands);
  add_about_command(
      root, commands,
      {.name = "rotate",
       .description = "Turn an object, or the whole plan, counter-clockwise",
       .footer = "Examples:\n"
                 "  roomcad rotate plan.json south --deg 90          # about its midpoint\n"
                 "  roomcad rotate plan.json view --deg -30 --about 6,4\n"
                 "  roomcad rotate plan.json --all --deg 90          # about the site centre\n"
                 "Multiples of 90 degrees are exact: four quarter turns give back the file.\n"
                 "A light's direction turns; a camera turns about its target by default.\n",
       .amount_option = "--deg",
       .amount_help = "angle in degrees, counter-clockwise",
       .one = rotate_object,
       .whole = rotate_all,
       .undo_is_exact = is_quarter_turn});
  add_about_command(
      root, commands,
      {.name = "scale",
       .description = "Scale an object, or the whole plan, in plan",
       .footer = "Examples:\n"
                 "  roomcad scale plan.json south --factor 1.5 --about 1,1\n"
                 "  roomcad scale plan.json --all --factor 0.5\n"
                 "Scales positions and lengths in plan (openings' offsets and widths with\n"
                 "their wall, the site's cell size with --all); heights and wall\n"
                 "thickness are kept.\n",
       .amount_option = "--factor",
       .amount_help = "scale factor, > 0",
       .one = scale_object,
       .whole = scale_all,
       .undo_is_exact = [](double) { return false; }});  // 1/factor is rarely a short decimal
}

}  // namespace roomcad::cli
