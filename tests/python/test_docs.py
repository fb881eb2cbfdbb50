# SPDX-License-Identifier: GPL-3.0-or-later
# docs/python.md's code blocks run, in order, in one namespace, in an empty folder.
import os
import re

from conftest import SOURCE_DIR


def test_every_code_block_of_the_python_guide_runs(tmp_path, capsys):
    text = (SOURCE_DIR / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 5
    namespace = {}
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        for number, block in enumerate(blocks, 1):
            exec(compile(block, f"docs/python.md block {number}", "exec"), namespace)
    finally:
        os.chdir(cwd)
    assert (tmp_path / "apartment.obj").stat().st_size > 0
    assert all(namespace["verdicts"].values())
