# SPDX-License-Identifier: GPL-3.0-or-later
# Every `build/roomcad ...` command shown in README.md and docs/cli.md runs, in order, and exits
# with the status its line states. The convention of those pages: a command exits 0 unless its
# comment says `exits N`. Only ```sh blocks run (```console blocks are sample transcripts), and
# of them only the lines that start with `build/roomcad`, except `roomcad view` (a window); the
# README's first block (the demo and test scripts) is skipped.
#
# Each page runs in a fresh folder that holds a copy of examples/ and an empty build/, with
# `build/roomcad` replaced by the built command, so the commands read the bundled files and
# write into that folder's build/, as they do from the repository root.
import os
import pathlib
import re
import shlex
import shutil
import subprocess

import pytest

from conftest import SOURCE_DIR

PAGES = ["README.md", "docs/cli.md"]
COMMAND = "build/roomcad"


def built_command():
    exe = os.environ.get("ROOMCAD_EXE") or str(SOURCE_DIR / "build" / "roomcad")
    if not os.access(exe, os.X_OK):
        pytest.fail(f"{exe} is not the built roomcad command (set ROOMCAD_EXE)")
    return exe


def split_comment(line):
    """Splits a shell line at its comment: a `#` at the start of a word, outside quotes."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def commands(page):
    """The (line number, argv, expected exit status) of every command the page runs."""
    text = (SOURCE_DIR / page).read_text()
    found = []
    block = 0
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            block += 1
            i += 1
            while i < len(lines) and lines[i].strip() != "```":
                number, line = i + 1, lines[i]
                while line.endswith("\\") and i + 1 < len(lines):
                    i += 1
                    line = line[:-1] + lines[i]
                i += 1
                if page == "README.md" and block == 1:
                    continue
                code, comment = split_comment(line.strip())
                if not code.startswith(COMMAND + " "):
                    continue
                argv = shlex.split(code)
                if argv[1] == "view":
                    continue
                status = re.search(r"\bexits (\d+)\b", comment)
                found.append((number, argv, int(status.group(1)) if status else 0))
        i += 1
    return found


def world(tmp_path):
    shutil.copytree(SOURCE_DIR / "examples", tmp_path / "examples")
    (tmp_path / "build").mkdir()
    return tmp_path


@pytest.mark.parametrize("page", PAGES)
def test_every_command_shown_runs_with_the_status_it_states(page, tmp_path):
    exe = built_command()
    folder = world(tmp_path)
    shown = commands(page)
    assert len(shown) >= 10, f"{page}: only {len(shown)} commands found"
    for number, argv, expected in shown:
        done = subprocess.run([exe, *argv[1:]], cwd=folder, capture_output=True, text=True,
                              timeout=600)
        assert done.returncode == expected, (
            f"{page}:{number}: `{shlex.join(argv)}` exited {done.returncode}, not {expected}\n"
            f"stdout:\n{done.stdout[-3000:]}\nstderr:\n{done.stderr[-3000:]}")


def test_the_readme_is_short_and_its_python_runs(tmp_path):
    readme = (SOURCE_DIR / "README.md").read_text()
    assert len(readme.splitlines()) <= 200
    assert readme.startswith("```sh\nbash scripts/demo.sh ")
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 1
    pytest.importorskip("roomcad")
    folder = world(tmp_path)
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        exec(compile(blocks[0], "README.md python block", "exec"), {})
    finally:
        os.chdir(cwd)
    assert (folder / "build" / "house.obj").stat().st_size > 0
