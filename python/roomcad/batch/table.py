# SPDX-License-Identifier: GPL-3.0-or-later
"""The results table: CSV or JSON lines (by RESULTS' extension), one row per plan, sorted by
path, written atomically; and its journal, RESULTS.partial, where each row is appended as it
arrives, so that the rows of a run that was killed are not lost (--resume reads both).

In CSV the per-code counts are `code=count` pairs joined by spaces and the outputs are joined
by `;`; JSON lines keep them as an object and a list. Cost: linear in the rows.
"""
import csv
import io
import json
import os

from .files import write_atomically
from .plan_task import COLUMNS
from .sources import BatchError

_JSON_SUFFIXES = (".jsonl", ".ndjson", ".json")
_NUMBERS = {"errors": int, "warnings": int, "walls": int, "openings": int, "levels": int,
            "repairs": int, "volume": float, "read_ms": float, "validate_ms": float,
            "build_ms": float}


def table_kind(path):
    """'csv' or 'jsonl' from RESULTS' extension. @raise BatchError for another"""
    name = str(path).lower()
    if name.endswith(".csv"):
        return "csv"
    if name.endswith(_JSON_SUFFIXES):
        return "jsonl"
    raise BatchError(f"{path}: RESULTS must end in .csv or .jsonl (JSON lines), not "
                     f"'{os.path.splitext(name)[1] or name}'")


def journal_path(path):
    return str(path) + ".partial"


def _csv_cell(column, value):
    if value is None:
        return ""
    if column.endswith("_codes"):
        return " ".join(f"{code}={count}" for code, count in value.items())
    if column == "outputs":
        return ";".join(value)
    return value


def _from_csv(record):
    row = {}
    for column in COLUMNS:
        text = record.get(column, "")
        if column.endswith("_codes"):
            row[column] = {k: int(v) for k, v in (p.split("=") for p in text.split())}
        elif column == "outputs":
            row[column] = text.split(";") if text else []
        elif column in _NUMBERS:
            row[column] = _NUMBERS[column](text) if text else None
        else:
            row[column] = text
    return row


def format_table(rows, kind):
    """The text of the table (rows sorted by path)."""
    ordered = sorted(rows, key=lambda r: r["path"])
    if kind == "jsonl":
        return "".join(json.dumps({c: r[c] for c in COLUMNS}) + "\n" for r in ordered)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(COLUMNS)
    for r in ordered:
        writer.writerow([_csv_cell(c, r[c]) for c in COLUMNS])
    return out.getvalue()


def write_table(path, rows):
    """Writes the table atomically and removes the journal."""
    write_atomically(path, format_table(rows, table_kind(path)))
    try:
        os.unlink(journal_path(path))
    except FileNotFoundError:
        pass


def _read_json_lines(path, lines):
    rows = []
    for number, line in enumerate(lines, 1):
        if not line.strip():
            continue
        try:
            rows.append(json.loads(line))
        except json.JSONDecodeError as error:
            if path.endswith(".partial") and number == len(lines):
                break  # the last line of a journal cut short by a kill: that plan runs again
            raise BatchError(f"{path}:{number}: not a row of results ({error.msg})") from None
    return rows


def read_rows(path):
    """The rows of an earlier run: RESULTS, then its journal (later rows win). Missing files
    give no rows. @raise BatchError for a file that is not a results table"""
    rows = {}
    for name in (str(path), journal_path(path)):
        try:
            with open(name, encoding="utf-8", newline="") as f:
                text = f.read()
        except FileNotFoundError:
            continue
        except OSError as error:
            raise BatchError(f"{name}: cannot read the results: {error}") from None
        if name.endswith(".partial") or table_kind(name) == "jsonl":
            found = _read_json_lines(name, text.splitlines())
        else:
            found = [_from_csv(r) for r in csv.DictReader(io.StringIO(text))]
        for row in found:
            if "path" not in row or "sha256" not in row:
                raise BatchError(f"{name}: not a results table of roomcad.batch (no path or "
                                 f"sha256 column)")
            rows[row["path"]] = row
    return rows


class Journal:
    """RESULTS.partial: rows appended as they arrive (flushed, not synced: a crash of the
    machine may lose the last ones, which --resume then runs again)."""

    def __init__(self, path, keep):
        """keep: append to the journal of an earlier run (--resume) rather than start anew.
        @raise BatchError when it cannot be written (before any plan runs)"""
        try:
            os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
            self._file = open(journal_path(path), "a" if keep else "w", encoding="utf-8")
        except OSError as error:
            raise BatchError(f"{path}: cannot write the results: {error.strerror}") from None

    def add(self, row):
        self._file.write(json.dumps(row) + "\n")
        self._file.flush()

    def close(self):
        self._file.close()
