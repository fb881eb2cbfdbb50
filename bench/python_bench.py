# SPDX-License-Identifier: GPL-3.0-or-later
"""What calling roomcad through Python costs (issue #21's speed targets).

1. build and validate of the 70 x 70 grid (testing/grid_plan.h, 9,940 walls) at 2 threads:
   the best of REPEATS runs through Python (Plan.validate; Plan.build(force=True), without the
   validation gate that build() runs first by default, as `roomcad build` does) against the
   same library calls from C++ (python_overhead_bench). Each side runs in ROUNDS fresh
   processes, taking turns, and the best of them all is reported, with every process's
   figure. Fresh processes because one process runs its repeats within a few percent of each
   other while two processes of the same side differ by up to 40% on a shared virtual machine
   (a 70 x 70 validate took 78 or 107 ms by the process); turns because the load changes from
   one minute to the next.
2. Plan.from_dict on the 100,800-wall grid (n = 224) given as a Python dict.

Run (after scripts/build.sh):
    PYTHONPATH=build/python python3 bench/python_bench.py [--build-dir build] [--repeats 5] [--rounds 6]
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import time

import roomcad


def best_ms(repeats, work):
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        work()
        best = min(best, (time.perf_counter() - start) * 1000)
    return best


def python_times(grid, repeats, threads):
    """One Python process's side: the best times of the calls on the plan in `grid`."""
    plan = roomcad.Plan.load(grid)
    return {"validate_ms": best_ms(repeats, lambda: plan.validate()),
            "build_ms": best_ms(repeats, lambda: plan.build(force=True, threads=threads)),
            "gated_ms": best_ms(repeats, lambda: plan.build(threads=threads))}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--repeats", type=int, default=5, help="calls timed in each process")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--rounds", type=int, default=6, help="processes per side, taking turns")
    parser.add_argument("--python-side", metavar="PLAN", help=argparse.SUPPRESS)  # one round's worker
    args = parser.parse_args()
    if args.python_side:
        print(json.dumps(python_times(args.python_side, args.repeats, args.threads)))
        return
    helper = pathlib.Path(args.build_dir) / "bench" / "python_overhead_bench"
    run = lambda command: json.loads(subprocess.run(command, check=True, capture_output=True,
                                                    text=True).stdout)
    with tempfile.TemporaryDirectory() as scratch:
        grid = pathlib.Path(scratch) / "grid70.json"
        cpp_rounds, py_rounds = [], []
        for _ in range(args.rounds):
            cpp_rounds.append(run([helper, "70", grid, str(args.repeats), str(args.threads)]))
            py_rounds.append(run([sys.executable, __file__, "--python-side", grid,
                                  "--repeats", str(args.repeats), "--threads", str(args.threads)]))
        cpp = {key: min(r[key] for r in cpp_rounds) for key in ("validate_ms", "build_ms")}
        py = {key: min(r[key] for r in py_rounds) for key in py_rounds[0]}

        big = pathlib.Path(scratch) / "grid224.json"
        subprocess.run([helper, "224", big, "0", "1"], check=True, capture_output=True)
        as_dict = json.loads(big.read_text())
        from_dict = best_ms(max(1, args.repeats // 2), lambda: roomcad.Plan.from_dict(as_dict))
        walls = len(as_dict["walls"])

    print(f"| call (70 x 70 grid, {cpp_rounds[0]['walls']} walls, {args.threads} threads, "
          f"best of {args.rounds} processes each) | C++ ms | Python ms | overhead |")
    print("| --- | --- | --- | --- |")
    for name in ("validate", "build"):
        c, p = cpp[name + "_ms"], py[name + "_ms"]
        print(f"| {name} | {c:.1f} | {p:.1f} | {100 * (p - c) / c:+.1f}% |")
    for side, rounds in (("C++", cpp_rounds), ("Python", py_rounds)):
        print(f"{side} processes: " + "; ".join(
            f"{name} " + " ".join(f"{r[name + '_ms']:.0f}" for r in rounds) for name in ("validate", "build")))
    print(f"\nPlan.build() with its validation gate (the default): {py['gated_ms']:.1f} ms")
    print(f"Plan.from_dict, {walls} walls: {from_dict:.0f} ms (target: under 1000 ms)")

if __name__ == "__main__":
    main()
