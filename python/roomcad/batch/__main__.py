# SPDX-License-Identifier: GPL-3.0-or-later
"""python3 -m roomcad.batch validate|repair|build|report SOURCE... --out RESULTS [options]."""
import argparse
import sys

from .engine import run
from .plan_task import ACTIONS
from .sources import BatchError

_DESCRIPTION = """\
Validate, repair, build or report many plans at once: each plan is one task on dask.distributed,
by default a LocalCluster of one worker process per core, or an existing cluster (--scheduler).
Each plan runs in a child process of its worker, so a plan that crashes it or runs past
--timeout is one `failed` row and the batch goes on.

  validate  the checks of `roomcad validate` (--rules); with --out-dir, NAME.findings.json
  repair    `roomcad repair` (--tolerance); with --out-dir, the repaired plan NAME.json
  build     `roomcad build` (refused for a plan with errors unless --force); with --out-dir,
            the model NAME.obj (--model-format)
  report    `roomcad report`; with --out-dir, the page NAME.html

SOURCE: a plan (.json, .sh3d or .ifc; the last two imported as `roomcad import` does), a folder
(searched recursively for those), or a text file listing plans or folders, one a line."""

_EPILOG = """\
RESULTS (.csv or .jsonl, JSON lines) has one row per plan, sorted by path: path, sha256 (of the
file), action, status, reason, errors, warnings, error_codes and warning_codes (counts per code;
in CSV `code=count` pairs), walls, openings, levels, repairs, volume (m^3, build), read_ms,
validate_ms, build_ms, outputs (in CSV joined by `;`). It is written atomically at the end, and
on Ctrl+C with every finished row; RESULTS.partial holds the rows as they arrive meanwhile.

status: ok (no errors), errors (the plan has errors), refused (not a plan, or a build of a plan
with errors), failed (the plan crashed its process or ran past --timeout; reason says which).

Exit status: 0 every plan ok; 1 some plan not ok; 2 could not run (bad arguments, a missing
SOURCE, an unreadable RESULTS); 130 interrupted (Ctrl+C; --resume goes on).

Examples:
  python3 -m roomcad.batch validate plans/ --out results.csv
  python3 -m roomcad.batch build plans/ --out built.jsonl --out-dir models/ --timeout 60
  python3 -m roomcad.batch validate plans/ --out results.csv --resume
  python3 -m roomcad.batch repair list.txt --out repaired.csv --out-dir fixed/ \\
      --scheduler tcp://10.0.0.1:8786
docs/batch.md: the benchmark, and a cluster of two hosts started by hand."""


def _parser():
    parser = argparse.ArgumentParser(prog="python3 -m roomcad.batch", description=_DESCRIPTION,
                                     epilog=_EPILOG,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("action", choices=ACTIONS, help="what to do with each plan")
    parser.add_argument("sources", nargs="+", metavar="SOURCE",
                        help="plans, folders of plans, or text files listing them")
    parser.add_argument("--out", required=True, metavar="RESULTS",
                        help="the results table to write: .csv or .jsonl")
    parser.add_argument("--out-dir", metavar="DIR",
                        help="where the outputs go, mirroring the sources' folders "
                             "(default: no outputs, only RESULTS)")
    parser.add_argument("--scheduler", metavar="tcp://HOST:PORT",
                        help="run on this Dask scheduler's cluster (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, metavar="N",
                        help="worker processes of the LocalCluster (default: one per core); "
                             "with --scheduler, wait until N workers have joined")
    parser.add_argument("--timeout", type=float, metavar="SECONDS",
                        help="kill a plan that takes longer and record it failed "
                             "(default: no limit)")
    parser.add_argument("--resume", action="store_true",
                        help="skip the plans whose row in RESULTS has the same content hash "
                             "(failed ones run again)")
    parser.add_argument("--no-isolation", dest="isolate", action="store_false",
                        help="run plans in the Dask workers themselves: a little quicker, but "
                             "a crash kills the worker (Dask restarts it and retries the plan) "
                             "and --timeout cannot be used")
    parser.add_argument("--rules", default="default", metavar="NAME|FILE",
                        help="rule set, as `roomcad validate --rules`: default, accessibility, "
                             "all, or a rules file (default: %(default)s)")
    parser.add_argument("--tolerance", type=float, default=0.01, metavar="METRES",
                        help="repair: how far an edit may move the solid (default: %(default)s)")
    parser.add_argument("--force", action="store_true",
                        help="build: build plans that have errors too")
    parser.add_argument("--model-format", default="obj",
                        choices=("obj", "off", "ply", "stl"),
                        help="build: the models' format under --out-dir (default: %(default)s)")
    parser.add_argument("--picture", action="store_true",
                        help="report: a rendered picture of the model in each page")
    parser.add_argument("--quiet", action="store_true", help="no progress, no summary")
    return parser


def main(argv=None):
    args = _parser().parse_args(argv)
    if args.workers is not None and args.workers < 1:
        _parser().error(f"--workers must be at least 1, not {args.workers}")
    if args.timeout is not None and not args.timeout > 0:
        _parser().error(f"--timeout must be a number of seconds > 0, not {args.timeout:g}")
    try:
        rows = run(args.sources, args.action, out=args.out, out_dir=args.out_dir,
                   scheduler=args.scheduler, workers=args.workers, timeout=args.timeout,
                   resume=args.resume, isolate=args.isolate,
                   progress=False if args.quiet else None, rules=args.rules,
                   tolerance=args.tolerance, force=args.force, model_format=args.model_format,
                   picture=args.picture)
    except BatchError as error:
        print(f"roomcad.batch: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    statuses = rows["status"].tolist() if hasattr(rows, "columns") else [r["status"] for r in rows]
    return 0 if all(s == "ok" for s in statuses) else 1


if __name__ == "__main__":
    sys.exit(main())
