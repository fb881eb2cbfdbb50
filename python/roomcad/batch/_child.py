# SPDX-License-Identifier: GPL-3.0-or-later
"""The child process of runner.py (python3 -m roomcad.batch._child): tasks as JSON lines on
stdin, each run in-process (plan_task.process_plan), its row as a JSON line on a private copy of
stdout, until stdin ends. The library's own stdout goes to stderr, so it cannot garble a row.

Test hook (tests/python/test_batch.py): ROOMCAD_BATCH_TEST_SIGNAL="NAME:SIGNAL,..." makes the
child send itself SIGNAL (e.g. KILL, STOP) when it starts on a plan whose file is named NAME:
a real crash or a real hang of the process, which the batch handles as any other.
"""
import json
import os
import signal
import sys

from .plan_task import process_plan


def _test_signals():
    wanted = {}
    for item in filter(None, os.environ.get("ROOMCAD_BATCH_TEST_SIGNAL", "").split(",")):
        name, _, sig = item.rpartition(":")
        wanted[name] = getattr(signal, "SIG" + sig)
    return wanted


def main():
    """The child: tasks from stdin, rows to the private copy of stdout, until stdin ends."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the batch's coordinator decides on Ctrl+C
    rows = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)
    wanted = _test_signals()
    for line in sys.stdin:
        task = json.loads(line)
        if os.path.basename(task["path"]) in wanted:
            os.kill(os.getpid(), wanted[os.path.basename(task["path"])])
        rows.write(json.dumps(process_plan(task)) + "\n")
        rows.flush()


if __name__ == "__main__":
    main()
