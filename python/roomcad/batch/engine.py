# SPDX-License-Identifier: GPL-3.0-or-later
"""roomcad.batch.run: the plans of SOURCEs as one task each, on dask.distributed (a LocalCluster
of one single-threaded worker per core, or the cluster of a given scheduler or client) or one
after another in this process (inline); their rows collected as they finish, journalled and
written as the results table at the end, or at Ctrl+C.

Cost: per plan, the plan's own work plus Dask's scheduling and, with isolation (the default),
a pipe round trip to the worker's child process (runner.py); docs/batch.md has the figures.
"""
import collections
import contextlib
import importlib.util
import logging
import os
import signal
import threading
import time
import uuid

from .plan_task import ACTIONS, DEFAULT_OPTIONS, failed_row, process_plan
from .progress import Progress
from .runner import run_isolated
from .sources import BatchError, check_outputs_apart, content_hash, find_plans
from .table import Journal, read_rows, table_kind, write_table


def _work(task, timeout, isolate):
    """A Dask task: one plan, in the worker's child process (isolate) or in the worker."""
    return run_isolated(task, timeout) if isolate else process_plan(task)


def _dashboard_address():
    """Dask's default address when its dashboard can run (Bokeh installed), else none."""
    return ":8787" if importlib.util.find_spec("bokeh") else None


@contextlib.contextmanager
def _sigint_ignored():
    """SIGINT ignored while processes are started, which then ignore it too (Python keeps an
    ignored SIGINT ignored), so that Ctrl+C stops the batch here and not in each worker."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def local_cluster(workers=None):
    """The LocalCluster of a batch: `workers` single-threaded worker processes (default: one
    per core), the dashboard when Bokeh is installed."""
    import dask
    from distributed import LocalCluster
    # worker-saturation inf: every task goes to a worker at once (work stealing evens them
    # out), so that no plan waits for a round trip to the scheduler after the one before
    # (Dask's queuing, meant for large graphs, tripled its cost per plan here: docs/batch.md).
    with _sigint_ignored(), dask.config.set({"distributed.scheduler.worker-saturation": "inf"}):
        return LocalCluster(n_workers=workers or os.cpu_count(), threads_per_worker=1,
                            processes=True, dashboard_address=_dashboard_address(),
                            silence_logs=logging.ERROR)


def _connect(client, scheduler, workers, say):
    """@return the client to use and what to close after the batch (what this call started)."""
    try:
        from distributed import Client
    except ImportError:
        raise BatchError("Dask's distributed is not installed (Debian: python3-distributed; "
                         "pip: distributed); inline=True runs the plans in this process "
                         "without it") from None
    if client is not None:
        return client, []
    if scheduler is not None:
        client = Client(scheduler)
        if workers:
            say(f"waiting for {workers} workers at {scheduler}")
            client.wait_for_workers(workers)
        return client, [client]
    cluster = local_cluster(workers)
    client = Client(cluster)
    if _dashboard_address():
        say(f"Dask dashboard: {cluster.dashboard_link}")
    return client, [client, cluster]


def _run_on_dask(tasks, record, client, timeout, isolate):
    from distributed import as_completed
    run_id = uuid.uuid4().hex[:12]
    keys = [f"roomcad-{task['action']}-{run_id}-{i}" for i, task in enumerate(tasks)]
    futures = client.map(_work, tasks, timeout=timeout, isolate=isolate, key=keys, pure=False)
    task_of = dict(zip(keys, tasks))
    # Results come with their futures, fetched in the background and handed over in batches:
    # a blocking result() per future would cost a round trip to a worker each.
    finished = as_completed(futures, with_results=True, raise_errors=False)
    try:
        for batch in finished.batches():
            for future, result in batch:
                if isinstance(result, BaseException):  # the worker itself died (KilledWorker
                    # after Dask's retries) or the task raised
                    result = failed_row(task_of[future.key], f"{type(result).__name__}: {result}")
                record(result)
                future.release()
    finally:
        client.cancel([f for f in futures if not f.done()])


def _plan_tasks(plans, action, out_dir, options, earlier):
    """The tasks still to run, and the rows of earlier (--resume) that stand: same path, same
    content hash, same action, not failed."""
    tasks, kept = [], []
    for path, mirrored in plans:
        sha = content_hash(path)
        row = earlier.get(str(path))
        if row and sha and row["sha256"] == sha and row["action"] == action \
                and row["status"] != "failed":
            kept.append(row)
            continue
        tasks.append({"path": str(path), "mirrored": str(mirrored), "sha256": sha,
                      "action": action, "out_dir": None if out_dir is None else str(out_dir),
                      "cwd": os.getcwd(), "options": options})
    return tasks, kept


def _summary(rows, seconds, ran):
    counts = collections.Counter(r["status"] for r in rows)
    statuses = ", ".join(f"{counts[s]} {s}" for s in ("ok", "errors", "refused", "failed"))
    rate = f", {ran / seconds:.1f} plans/s" if ran and seconds > 0 else ""
    return f"{len(rows)} plans: {statuses}; {ran} run in {seconds:.1f} s (start-up included){rate}"


def _as_result(rows):
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


def run(sources, action="validate", *, out=None, out_dir=None, client=None, scheduler=None,
        workers=None, timeout=None, resume=False, isolate=True, inline=False, progress=None,
        rules="default", tolerance=0.01, force=False, model_format="obj", picture=False):
    """Validates, repairs, builds or reports every plan of `sources` (docs/batch.md).

    @param sources   plans (.json, .sh3d, .ifc), folders (searched recursively) or text files
                     listing them, one a line
    @param action    'validate', 'repair', 'build' or 'report', as the `roomcad` commands
    @param out       the results table (.csv or .jsonl), written atomically; None: not written
    @param out_dir   where outputs go (findings JSON, repaired plans, models, report pages),
                     mirroring the sources' folders; None: no outputs
    @param client    a distributed.Client to run on; else `scheduler` (an address such as
                     tcp://host:8786), else a LocalCluster of `workers` processes (default:
                     one per core)
    @param workers   with a scheduler: wait until this many workers have joined
    @param timeout   seconds a plan may take before it is killed and recorded failed
    @param resume    keep the rows of `out` whose plan has the same content hash (not failed)
    @param isolate   run each plan in a child process of its worker, so that a crash or a
                     hang costs that plan only (False: in the worker itself, no timeout)
    @param inline    no Dask: one plan after another in this process (in a child process
                     with `isolate`)
    @param progress  None: a bar on a terminal, plain lines otherwise; False: nothing
    @param rules, tolerance, force, model_format, picture: as the commands' --rules,
                     repair's --tolerance, build's --force, build's format (obj, off, ply,
                     stl), report's --picture
    @return the rows sorted by path: a pandas DataFrame when pandas is installed, else a list
            of dicts
    @raise BatchError for SOURCEs or a results file that cannot be used; KeyboardInterrupt
           after writing every finished row, when interrupted
    """
    if action not in ACTIONS:
        raise BatchError(f"action: '{action}' is not one of {', '.join(ACTIONS)}")
    if resume and out is None:
        raise BatchError("resume: needs the results table of the earlier run (out)")
    if timeout is not None and not isolate:
        raise BatchError("timeout (--timeout) needs isolation (not --no-isolation): a plan "
                         "is stopped by killing the process running it")
    if out is not None:
        table_kind(out)
    plans = find_plans(sources)
    check_outputs_apart(plans, out_dir)
    options = dict(DEFAULT_OPTIONS, rules=rules, tolerance=tolerance, force=force,
                   model_format=model_format, picture=picture)
    tasks, kept = _plan_tasks(plans, action, out_dir, options, read_rows(out) if resume else {})
    shown = Progress(len(tasks)) if progress is not False else None
    say = shown.finish if shown else (lambda message: None)
    if resume:
        say(f"resume: {len(kept)} of {len(plans)} plans done already; running {len(tasks)}")
    journal = Journal(out, keep=resume) if out is not None else None
    rows = list(kept)

    def record(row):
        rows.append(row)
        if journal:
            journal.add(row)
        if shown:
            shown.add(row)

    start, owned = time.monotonic(), []
    try:
        if inline:
            for task in tasks:
                record(run_isolated(task, timeout) if isolate else process_plan(task))
        elif tasks:
            client, owned = _connect(client, scheduler, workers, say)
            if shown:
                shown.start_clock()
            _run_on_dask(tasks, record, client, timeout, isolate)
    except KeyboardInterrupt:
        say(f"interrupted: {len(rows) - len(kept)} of {len(tasks)} plans done"
            + (f", written to {out}; --resume runs the others" if out is not None else ""))
        raise
    finally:
        if journal:
            journal.close()
            write_table(out, rows)
        for thing in owned:
            thing.close()
    say(_summary(rows, time.monotonic() - start, len(rows) - len(kept))
        + (f"; results in {out}" if out is not None else ""))
    return _as_result(sorted(rows, key=lambda r: r["path"]))
