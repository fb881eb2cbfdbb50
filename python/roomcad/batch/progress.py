# SPDX-License-Identifier: GPL-3.0-or-later
"""Progress of a batch on stderr: on a terminal one line redrawn in place (a bar, plans done,
failed, per second, time left); otherwise a plain line at each tenth of the batch and at least
every 30 seconds, which logs and CI keep readable. Cost: one short write per redraw, at most
ten redraws a second.
"""
import sys
import time


def _duration(seconds):
    seconds = int(seconds + 0.5)
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"


class Progress:
    def __init__(self, total, stream=None, bar=None):
        """bar: redraw one line (default: when `stream` is a terminal)."""
        self.stream = stream or sys.stderr
        self.bar = self.stream.isatty() if bar is None else bar
        self.total, self.done, self.failed = total, 0, 0
        self.start = self._shown = time.monotonic()
        self._next_tenth = 1

    def start_clock(self):
        """Rates count from now (after a cluster's start-up, which is no plan's)."""
        self.start = self._shown = time.monotonic()

    def _line(self):
        elapsed = max(time.monotonic() - self.start, 1e-9)
        rate = self.done / elapsed
        left = _duration((self.total - self.done) / rate) if rate > 0 else "?"
        return (f"{self.done}/{self.total} plans, {self.failed} failed, {rate:.1f}/s, "
                f"{left} left")

    def add(self, row):
        self.done += 1
        self.failed += row["status"] == "failed"
        now = time.monotonic()
        if self.bar:
            if now - self._shown >= 0.1 or self.done == self.total:
                filled = 30 * self.done // max(self.total, 1)
                self.stream.write(f"\r[{'#' * filled}{'.' * (30 - filled)}] {self._line()}\x1b[K")
                self.stream.flush()
                self._shown = now
        elif self.done * 10 >= self._next_tenth * self.total or now - self._shown >= 30:
            self.stream.write(f"batch: {self._line()}\n")
            self.stream.flush()
            self._shown = now
            self._next_tenth = self.done * 10 // max(self.total, 1) + 1

    def finish(self, message):
        if self.bar:
            self.stream.write("\n")
        self.stream.write(f"batch: {message}\n")
        self.stream.flush()
