# SPDX-License-Identifier: GPL-3.0-or-later
"""roomcad.batch: validate, repair, build or report folders of plans at once, on this machine's
cores or a Dask cluster, with a results table of one row per plan (docs/batch.md).

From the shell: ``python3 -m roomcad.batch validate plans/ --out results.csv``; from Python:
``roomcad.batch.run(["plans/"], action="validate", out="results.csv")``.
"""
from .engine import run
from .plan_task import ACTIONS, COLUMNS, STATUSES, TIMING_COLUMNS, process_plan
from .sources import BatchError, find_plans

__all__ = ["ACTIONS", "BatchError", "COLUMNS", "STATUSES", "TIMING_COLUMNS", "find_plans",
           "process_plan", "run"]
