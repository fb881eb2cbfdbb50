# SPDX-License-Identifier: GPL-3.0-or-later
"""What calling roomcad through Python costs (issue #21's speed targets).

1. build and validate of the 70 x 70 grid (testing/grid_plan.h, 9,940 walls) at 2 threads:
   the best of REPEATS runs through Python (Plan.validate; Plan.build(force=True), without the
   validation gate that build() runs first by default, as `roomcad build` does) against the
   same library calls from C++ (python_overhead_bench, run before and after the Python runs,
   the better kept: on a shared machine the load changes from one minute to the next);
2. Plan.from_dict on the 100,800-wall grid (n = 224) given as a Python dict.

Run (after scripts/build.sh):
    PYTHONPATH=build/python python3 bench/python_bench.py [--build-dir build] [--repeats 5]
"""
import argparse
import json
import pathlib
import subprocess
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    helper = pathlib.Path(args.build_dir) / "bench" / "python_overhead_bench"
    with tempfile.TemporaryDirectory() as scratch:
        grid = pathlib.Path(scratch) / "grid70.json"
        def cpp_times():
            return json.loads(subprocess.run([helper, "70", grid, str(args.repeats), str(args.threads)],
                                             check=True, capture_output=True, text=True).stdout)
        before = cpp_times()
        plan = roomcad.Plan.load(grid)
        py_validate = best_ms(args.repeats, lambda: plan.validate())
        py_build = best_ms(args.repeats, lambda: plan.build(force=True, threads=args.threads))
        py_gated = best_ms(args.repeats, lambda: plan.build(threads=args.threads))
        after = cpp_times()
        cpp = {key: min(before[key], after[key]) for key in ("validate_ms", "build_ms")}
        cpp["walls"] = before["walls"]

        big = pathlib.Path(scratch) / "grid224.json"
        subprocess.run([helper, "224", big, "0", "1"], check=True, capture_output=True)
        as_dict = json.loads(big.read_text())
        from_dict = best_ms(max(1, args.repeats // 2), lambda: roomcad.Plan.from_dict(as_dict))
        walls = len(as_dict["walls"])

    print(f"| call (70 x 70 grid, {cpp['walls']} walls, {args.threads} threads) | C++ ms | Python ms | overhead |")
    print("| --- | --- | --- | --- |")
    for name, c, p in (("validate", cpp["validate_ms"], py_validate), ("build", cpp["build_ms"], py_build)):
        print(f"| {name} | {c:.1f} | {p:.1f} | {100 * (p - c) / c:+.1f}% |")
    print(f"\nPlan.build() with its validation gate (the default): {py_gated:.1f} ms")
    print(f"Plan.from_dict, {walls} walls: {from_dict:.0f} ms (target: under 1000 ms)")


if __name__ == "__main__":
    main()
