# SPDX-License-Identifier: GPL-3.0-or-later
# What the Python tests share: where the repository and the `roomcad` command are (CTest sets
# ROOMCAD_SOURCE_DIR and ROOMCAD_EXE, and PYTHONPATH to the built module), running the command,
# and reading its PNGs (zlib and the five PNG filters: no imaging package needed).
import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ROOMCAD_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = sorted((SOURCE_DIR / "examples").glob("*.json"))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def roomcad_exe():
    exe = os.environ.get("ROOMCAD_EXE")
    if not exe or not os.access(exe, os.X_OK):
        pytest.fail("ROOMCAD_EXE must name the built roomcad command (CTest sets it)")
    return exe


def run_cli(exe, *args, check=True):
    """Runs `roomcad args...`; returns the CompletedProcess (stdout as bytes)."""
    done = subprocess.run([exe, *map(str, args)], capture_output=True)
    if check and done.returncode != 0:
        raise AssertionError(f"roomcad {' '.join(map(str, args))}: exit {done.returncode}\n"
                             f"{done.stderr.decode()}")
    return done


def read_png_rgb(path):
    """Decodes an 8-bit RGB, non-interlaced PNG (what `roomcad render` writes) to H x W x 3."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert (depth, colour, interlace) == (8, 2, 0), f"{path}: not 8-bit RGB non-interlaced"
    raw = zlib.decompress(idat)
    stride = width * 3
    out = np.zeros((height, stride), dtype=np.uint8)
    previous = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        if kind == 0:
            line = row
        elif kind == 2:
            line = (row + previous) & 0xFF
        else:  # 1 sub, 3 average, 4 Paeth: left neighbours, pixel by pixel
            line = np.zeros(stride, dtype=np.int32)
            for x in range(stride):
                a = line[x - 3] if x >= 3 else 0
                b = previous[x]
                c = previous[x - 3] if x >= 3 else 0
                if kind == 1:
                    predictor = a
                elif kind == 3:
                    predictor = (a + b) // 2
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (row[x] + predictor) & 0xFF
        out[y] = line
        previous = line
    return out.reshape(height, width, 3)
