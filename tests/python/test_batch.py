# SPDX-License-Identifier: GPL-3.0-or-later
# roomcad.batch (docs/batch.md): a Dask LocalCluster gives the rows of an in-process loop; a
# plan that kills its process or hangs is one failed row; --resume after Ctrl+C finishes the
# table without running a plan twice; imports and bad SOURCEs.
import json
import os
import pathlib
import signal
import subprocess
import sys
import time

import pytest

pytest.importorskip("distributed")

import roomcad.batch  # noqa: E402
from grid_plans import write_grid_plans  # noqa: E402
from roomcad.batch.table import read_rows  # noqa: E402

SOURCE_DIR = pathlib.Path(os.environ.get("ROOMCAD_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
HOMES = pathlib.Path("examples/sweethome3d/homes/eteks-example-homes")


def as_rows(result):
    """run() gives a DataFrame when pandas is installed, else a list of dicts."""
    return result.to_dict("records") if hasattr(result, "to_dict") else result


def without_timings(rows):
    return [{k: v for k, v in r.items() if k not in roomcad.batch.TIMING_COLUMNS} for r in rows]


def batch_command(*args):
    return [sys.executable, "-m", "roomcad.batch", *map(str, args)]


def batch_env():
    """The environment, with the folder this roomcad was imported from first on PYTHONPATH
    (which may name it relative to the test's working folder)."""
    found = str(pathlib.Path(roomcad.batch.__file__).parents[2])
    return dict(os.environ, PYTHONPATH=os.pathsep.join([found, os.environ.get("PYTHONPATH", "")]))


def test_a_cluster_of_two_workers_gives_the_rows_of_an_in_process_loop(tmp_path):
    write_grid_plans(tmp_path / "plans", 500, smallest=8, largest=60)
    loop = as_rows(roomcad.batch.run([tmp_path / "plans"], "build", inline=True, isolate=False,
                                     progress=False))
    cluster = as_rows(roomcad.batch.run([tmp_path / "plans"], "build", workers=2,
                                        out=tmp_path / "results.csv", progress=False))
    assert len(loop) == 500
    assert {r["status"] for r in loop} == {"ok", "refused"}  # every 7th has an error
    assert all(r["volume"] > 0 for r in loop if r["status"] == "ok")
    assert without_timings(cluster) == without_timings(loop)
    written = sorted(read_rows(tmp_path / "results.csv").values(), key=lambda r: r["path"])
    assert without_timings(written) == without_timings(loop)


def test_a_plan_that_kills_its_process_or_hangs_is_one_failed_row(tmp_path, monkeypatch):
    plans = write_grid_plans(tmp_path / "plans", 40, smallest=8, largest=40)
    for name in ("crash.json", "hang.json"):
        (tmp_path / "plans" / name).write_bytes(plans[0].read_bytes())
    # The worker's child process sends itself SIGKILL on crash.json and SIGSTOP on hang.json
    # (the test hook of roomcad/batch/_child.py): a real death and a real hang.
    monkeypatch.setenv("ROOMCAD_BATCH_TEST_SIGNAL", "crash.json:KILL,hang.json:STOP")
    rows = as_rows(roomcad.batch.run([tmp_path / "plans"], "validate", workers=2, timeout=2,
                                     out=tmp_path / "results.jsonl", progress=False))
    by_name = {pathlib.Path(r["path"]).name: r for r in rows}
    assert len(rows) == 42 and len(by_name) == 42
    assert by_name["crash.json"]["status"] == "failed"
    assert "killed by SIGKILL" in by_name["crash.json"]["reason"]
    assert by_name["hang.json"]["status"] == "failed"
    assert "timed out after 2 s" in by_name["hang.json"]["reason"]
    others = [r for name, r in by_name.items() if name not in ("crash.json", "hang.json")]
    assert {r["status"] for r in others} == {"ok", "errors"}
    assert all(r["walls"] > 0 for r in others)


def test_resume_after_ctrl_c_finishes_the_table_running_no_plan_twice(tmp_path):
    write_grid_plans(tmp_path / "plans", 300)
    results = tmp_path / "results.jsonl"
    first = subprocess.Popen(batch_command("build", tmp_path / "plans", "--out", results,
                                           "--workers", "1"),
                             stderr=subprocess.PIPE, text=True)
    journal = pathlib.Path(str(results) + ".partial")
    while not journal.exists() or journal.read_text().count("\n") < 30:
        assert first.poll() is None, first.stderr.read()
        time.sleep(0.02)
    first.send_signal(signal.SIGINT)
    _, stderr = first.communicate(timeout=60)
    assert first.returncode == 130, stderr
    assert "interrupted" in stderr
    assert not journal.exists()
    done = read_rows(results)
    assert 30 <= len(done) < 300

    second = subprocess.run(batch_command("build", tmp_path / "plans", "--out", results,
                                          "--resume", "--workers", "1"),
                            capture_output=True, text=True)
    assert second.returncode == 1, second.stderr  # some plans have errors
    assert f"resume: {len(done)} of 300 plans done already; running {300 - len(done)}" \
        in second.stderr
    final = read_rows(results)
    lines = results.read_text().splitlines()
    assert len(lines) == 300 and len(final) == 300
    for path, row in done.items():  # timings and all: the row of the first run, not a new one
        assert final[path] == row


def test_imported_plans_and_a_list_of_paths(tmp_path):
    listing = tmp_path / "plans.txt"
    listing.write_text("# an IFC model and a Sweet Home 3D home\n"
                       f"{SOURCE_DIR / 'examples/ifc/duplex.ifc'}\n"
                       f"{SOURCE_DIR / HOMES / '1-BedroomApartment.Home.xml'}\n")
    rows = as_rows(roomcad.batch.run([listing], "repair", inline=True, isolate=False,
                                     out_dir=tmp_path / "out", progress=False))
    assert [pathlib.Path(r["path"]).name for r in rows] == ["duplex.ifc",
                                                           "1-BedroomApartment.Home.xml"]
    assert all(r["status"] in ("ok", "errors") and r["walls"] > 0 for r in rows)
    assert rows[1]["repairs"] > 0  # its wall drawn along another, its doors over one another
    for row, name in zip(rows, ("duplex.json", "1-BedroomApartment.Home.json")):
        repaired = json.loads((tmp_path / "out" / name).read_text())
        assert row["outputs"] == [str(tmp_path / "out" / name)]
        assert len(repaired["walls"]) == row["walls"]


@pytest.mark.parametrize("args, message", [
    (["nowhere", "--out", "r.csv"], "nowhere: no such file or folder"),
    (["plans", "--out", "r.txt"], "r.txt: RESULTS must end in .csv or .jsonl"),
    (["plans", "--out", "r.csv", "--no-isolation", "--timeout", "5"],
     "timeout (--timeout) needs isolation (not --no-isolation)"),
])
def test_a_batch_that_cannot_run_says_why_and_writes_nothing(tmp_path, args, message):
    write_grid_plans(tmp_path / "plans", 2)
    done = subprocess.run(batch_command("validate", *args), cwd=tmp_path, env=batch_env(),
                          capture_output=True, text=True)
    assert done.returncode == 2
    assert message in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plans"]


def test_help_explains_the_columns_and_statuses():
    done = subprocess.run(batch_command("--help"), capture_output=True, text=True)
    assert done.returncode == 0
    for word in ("--scheduler", "--resume", "--timeout", "failed", "error_codes", "Exit status"):
        assert word in done.stdout
