# SPDX-License-Identifier: GPL-3.0-or-later
"""Crash and timeout isolation: each thread that runs plans (a Dask worker's, or the caller's)
keeps one child process, started once, that runs them one after another in-process
(plan_task.process_plan). A plan that kills that process, or runs past the timeout (the
process is then killed), becomes one `failed` row; the next plan starts a new process.

Protocol: one JSON line per task on the child's stdin, one JSON line per row back on a private
copy of its stdout (the library's own stdout goes to stderr, so it cannot garble a row).
Cost: one process start (about the import of roomcad) per thread, then a pipe round trip and a
JSON encoding of the task and the row per plan; a crash or a timeout costs one more start.
The child is _child.py.
"""
import json
import os
import selectors
import signal
import subprocess
import sys
import threading
import time

from .plan_task import failed_row


def _describe_exit(code):
    if code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit status {code}"


class Runner:
    """One child process running plans, restarted after a crash or a timeout."""

    def __init__(self):
        self._child = None
        self._pending = b""

    def _start(self):
        self._child = subprocess.Popen([sys.executable, "-m", "roomcad.batch._child"],
                                       stdin=subprocess.PIPE, stdout=subprocess.PIPE, bufsize=0)
        self._pending = b""

    def _read_line(self, deadline):
        """The child's next line, or None at its end (it died) or at the deadline (None: none)."""
        fd = self._child.stdout.fileno()
        with selectors.DefaultSelector() as selector:
            selector.register(fd, selectors.EVENT_READ)
            while b"\n" not in self._pending:
                wait = None if deadline is None else deadline - time.monotonic()
                if wait is not None and wait <= 0:
                    return None, "timeout"
                if not selector.select(wait):
                    continue
                chunk = os.read(fd, 1 << 16)
                if not chunk:
                    return None, "died"
                self._pending += chunk
        line, self._pending = self._pending.split(b"\n", 1)
        return line, None

    def _stop(self):
        self._child.kill()
        code = self._child.wait()
        self._child.stdin.close()
        self._child.stdout.close()
        self._child = None
        return code

    def run(self, task, timeout=None):
        """Runs a task in the child. @return its row; a `failed` row for a crash or timeout"""
        if self._child is None:
            self._start()
        deadline = None if timeout is None else time.monotonic() + timeout
        try:
            self._child.stdin.write((json.dumps(task) + "\n").encode())
            line, why = self._read_line(deadline)
        except BrokenPipeError:
            line, why = None, "died"
        if line is not None:
            return json.loads(line)
        if why == "timeout":
            self._stop()
            return failed_row(task, f"timed out after {timeout:g} s (--timeout); its process "
                                    f"was killed and a new one started")
        code = self._stop()
        return failed_row(task, f"the process running it died ({_describe_exit(code)}); a new "
                                f"one was started")

    def close(self):
        if self._child is not None:
            self._child.stdin.close()
            self._child.wait()
            self._child.stdout.close()
            self._child = None


_per_thread = threading.local()


def run_isolated(task, timeout=None):
    """Runs a task in this thread's child process (started on first use). @return its row"""
    runner = getattr(_per_thread, "runner", None)
    if runner is None:
        runner = _per_thread.runner = Runner()
    return runner.run(task, timeout)
