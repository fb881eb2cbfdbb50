# SPDX-License-Identifier: GPL-3.0-or-later
"""One plan of a batch, in this process: read (or import) it, validate it, then repair, build or
report it as the `roomcad` command would, and describe the outcome as one row of the results.

A task is a dict: path, mirrored (the relative path its outputs mirror), sha256, action, out_dir
(or None), cwd (what relative paths are relative to: a worker on another host has its own
working folder) and options (rules, tolerance, force, model_format, picture). Rows name the
files as the task does. A row is a dict of
COLUMNS. Cost: the plan's own (reading, validation, and the action's work); the row is a few
hundred bytes.
"""
import collections
import os
import pathlib
import time

import roomcad

from .files import write_atomically

ACTIONS = ("validate", "repair", "build", "report")

#: The columns of a results row, in order.
COLUMNS = ("path", "sha256", "action", "status", "reason", "errors", "warnings", "error_codes",
           "warning_codes", "walls", "openings", "levels", "repairs", "volume", "read_ms",
           "validate_ms", "build_ms", "outputs")

#: The columns that measure time: they differ from run to run.
TIMING_COLUMNS = ("read_ms", "validate_ms", "build_ms")

#: ok: no errors; errors: the plan has errors (the action still ran where the command runs it);
#: refused: the file is not a plan, or the action refused the plan (a build with errors);
#: failed: the plan crashed or hung the process running it, or ran past --timeout.
STATUSES = ("ok", "errors", "refused", "failed")

DEFAULT_OPTIONS = {"rules": "default", "tolerance": 0.01, "force": False, "model_format": "obj",
                   "picture": False}

#: The suffix of each action's output under out_dir (build: the model's format).
_OUTPUT_SUFFIX = {"validate": ".findings.json", "repair": ".json", "report": ".html"}


def empty_row(task):
    """The row of a task before anything is known of the plan."""
    row = dict.fromkeys(COLUMNS)
    row.update(path=str(task["path"]), sha256=task["sha256"], action=task["action"], reason="",
               error_codes={}, warning_codes={}, outputs=[])
    return row


def failed_row(task, reason):
    """The row of a plan that did not finish: status failed, with the reason."""
    row = empty_row(task)
    row.update(status="failed", reason=reason)
    return row


def read_plan(path):
    """A plan from its file: JSON as it is, Sweet Home 3D and IFC imported as `roomcad import`
    imports them. @raise roomcad.Error naming the file"""
    suffix = pathlib.Path(path).suffix.lower()
    if suffix == ".ifc":
        return roomcad.import_ifc(path)
    if suffix in (".sh3d", ".xml"):
        return roomcad.import_sweethome3d(path)
    return roomcad.Plan.load(path)


def _count_findings(row, report, import_warnings):
    errors = collections.Counter(f.code for f in report.errors)
    warnings = collections.Counter(f.code for f in list(report.warnings) + list(import_warnings))
    row.update(errors=sum(errors.values()), warnings=sum(warnings.values()),
               error_codes=dict(sorted(errors.items())),
               warning_codes=dict(sorted(warnings.items())))


def _located(task, path):
    """Where `path` (as the task names it) is on this host: as named, in the batch's working
    folder (so that roomcad's messages name it as given), else under that folder's path."""
    return path if os.getcwd() == task["cwd"] else os.path.join(task["cwd"], path)


def _output_path(task, suffix):
    """The output's path as rows name it; its folder made."""
    mirrored = pathlib.PurePath(task["mirrored"])
    path = pathlib.Path(task["out_dir"], mirrored.parent, mirrored.stem + suffix)
    if os.path.abspath(_located(task, path)) == os.path.abspath(_located(task, task["path"])):
        raise roomcad.Error(f"{path}: the output would replace its source plan; give another "
                            f"--out-dir")
    os.makedirs(_located(task, path.parent), exist_ok=True)
    return path


def _milliseconds(start):
    return round((time.perf_counter() - start) * 1000.0, 3)


def _act(task, plan, report, row):
    """Runs the task's action on a plan that reads; fills the row. @return the report that
    decides the status (after the repair, for repair)"""
    action, options, out = task["action"], task["options"], task["out_dir"] is not None
    if action == "validate" and out:
        path = _output_path(task, _OUTPUT_SUFFIX[action])
        write_atomically(_located(task, path), report.to_json())
        row["outputs"].append(str(path))
    elif action == "repair":
        done = plan.repair(tolerance=options["tolerance"])
        row["repairs"] = len(done.get("edits", []))
        report = plan.validate(options["rules"])
        if out:
            path = _output_path(task, _OUTPUT_SUFFIX[action])
            plan.save(_located(task, path))
            row["outputs"].append(str(path))
    elif action == "build":
        if not report.ok and not options["force"]:
            errors = row["errors"]
            row.update(status="refused", reason=f"build: the plan has {errors} error"
                                                f"{'s' if errors != 1 else ''} (first: "
                                                f"{report.errors[0].message}) --force builds "
                                                f"it anyway")
            return report
        start = time.perf_counter()
        model = plan.build(force=True, threads=1)  # the batch runs plans side by side
        row["volume"] = round(model.volume, 9)
        if out:
            path = _output_path(task, "." + options["model_format"])
            model.save(_located(task, path))
            row["outputs"].append(str(path))
            if options["model_format"] == "obj":
                row["outputs"].append(str(path.with_suffix(".mtl")))
        row["build_ms"] = _milliseconds(start)
    elif action == "report" and out:
        path = _output_path(task, _OUTPUT_SUFFIX[action])
        write_atomically(_located(task, path), report.to_html(picture=options["picture"]))
        row["outputs"].append(str(path))
    return report


def process_plan(task):
    """Runs one task here, in this process. @return its row (never raises for a plan: a plan
    roomcad refuses is a `refused` row, with roomcad's message)"""
    row = empty_row(task)
    options = task["options"]
    try:
        start = time.perf_counter()
        plan = read_plan(_located(task, task["path"]))
        row["read_ms"] = _milliseconds(start)
        row.update(walls=len(plan.ids("wall")),
                   openings=len(plan.ids("door")) + len(plan.ids("window")),
                   levels=max(1, len(plan.ids("level"))))  # none: one
        start = time.perf_counter()
        report = plan.validate(options["rules"])
        row["validate_ms"] = _milliseconds(start)
        _count_findings(row, report, plan.import_warnings)
        report = _act(task, plan, report, row)
        if task["action"] == "repair":
            _count_findings(row, report, plan.import_warnings)
    except roomcad.Error as error:
        row.update(status="refused", reason=f"{getattr(error, 'code', 'error')}: {error}")
        return row
    except OSError as error:
        row.update(status="refused", reason=f"io_error: {error}")
        return row
    if row["status"] is None:
        row["status"] = "ok" if report.ok else "errors"
    return row
