# SPDX-License-Identifier: GPL-3.0-or-later
"""roomcad.batch's throughput (issue #62): PLANS generated plans of 20-200 walls
(tests/python/grid_plans.py), validated and built, in plans per second:

- in-process: run(inline=True, isolate=False), a plain loop in this process;
- isolated: run(inline=True), the same loop through one child process (runner.py): the cost
  of crash and timeout isolation, per plan;
- Dask, 1 worker and 2 workers: a LocalCluster started and warmed (a few plans) before the
  clock starts (that start-up is reported apart), each plan in its worker's child process
  (the default);
- Dask, 1 worker, --no-isolation: the plans in the worker itself.

Dask's overhead per plan is (Dask 1 worker - isolated) / PLANS: scheduling, the task and its row
through the scheduler, and the coordinator's bookkeeping. Timings vary with the machine's load:
run it on an idle machine (the figures of docs/batch.md were taken on 2 shared cores).

Run (after scripts/build.sh):
    PYTHONPATH=build/python python3 bench/batch_bench.py [--plans 10000] [--actions validate,build]
"""
import argparse
import pathlib
import sys
import tempfile
import time

import roomcad.batch
from distributed import Client
from roomcad.batch.engine import local_cluster

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests" / "python"))
from grid_plans import write_grid_plans  # noqa: E402


def seconds(work):
    start = time.perf_counter()
    rows = work()
    return time.perf_counter() - start, rows


def on_cluster(workers, action, folder, isolate):
    start = time.perf_counter()
    with local_cluster(workers) as cluster, Client(cluster) as client:
        # Warm: each worker imports roomcad and starts its child process on its first plan.
        roomcad.batch.run(sorted(folder.rglob("*.json"))[:4 * workers], action, client=client,
                          isolate=isolate, progress=False)
        started = time.perf_counter() - start
        took, rows = seconds(lambda: roomcad.batch.run([folder], action, client=client,
                                                       isolate=isolate, progress=False))
    return started, took, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plans", type=int, default=10000)
    parser.add_argument("--actions", default="validate,build")
    args = parser.parse_args()
    n = args.plans
    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(scratch) / "plans"
        took, _ = seconds(lambda: write_grid_plans(folder, n))
        print(f"{n} plans of 20-200 walls written in {took:.1f} s")
        print("| action | how | s | plans/s | per plan, ms | rows |")
        print("| --- | --- | --- | --- | --- | --- |")
        for action in args.actions.split(","):
            figures = {}

            def show(how, took, rows):
                figures[how] = took
                statuses = sorted({r["status"] for r in rows})
                print(f"| {action} | {how} | {took:.1f} | {n / took:.0f} | "
                      f"{1000 * took / n:.2f} | {len(rows)} {'/'.join(statuses)} |", flush=True)

            show("in-process", *seconds(lambda: roomcad.batch.run(
                [folder], action, inline=True, isolate=False, progress=False)))
            show("isolated, in this process", *seconds(lambda: roomcad.batch.run(
                [folder], action, inline=True, progress=False)))
            for workers, isolate in ((1, True), (2, True), (1, False)):
                how = f"Dask, {workers} worker{'s' if workers > 1 else ''}" + \
                    ("" if isolate else ", --no-isolation")
                started, took, rows = on_cluster(workers, action, folder, isolate)
                show(how, took, rows)
                print(f"|   | (cluster start-up and warm-up {started:.1f} s, not counted) "
                      f"| | | | |")
            dask = 1000 * (figures["Dask, 1 worker"] - figures["isolated, in this process"]) / n
            isolation = 1000 * (figures["isolated, in this process"] - figures["in-process"]) / n
            print(f"{action}: Dask's overhead {dask:.2f} ms a plan; isolation's {isolation:.2f} "
                  f"ms a plan; 2 workers / 1 worker = "
                  f"{figures['Dask, 1 worker'] / figures['Dask, 2 workers']:.2f}x", flush=True)


if __name__ == "__main__":
    main()
