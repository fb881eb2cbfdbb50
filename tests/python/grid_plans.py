# SPDX-License-Identifier: GPL-3.0-or-later
"""Generated plans for the batch tests and bench/batch_bench.py: a grid of rooms, 3 m square,
whose walls are the grid's segments, with a door in every inner wall and a window in every
outer one. Every seventh plan has a second window over the first of its outer walls (an
opening_overlap error), so that a batch has plans of both statuses.
"""
import json


def _grid_for(walls):
    """Columns and rows whose grid has about `walls` segments: c*(r+1) + r*(c+1)."""
    columns = max(1, round((walls / 2) ** 0.5))
    rows = max(1, round((walls - columns) / (2 * columns + 1)))
    return columns, rows


def grid_plan(walls, number=0):
    """The plan dict of about `walls` walls (at least 4); `number` picks the error plans."""
    columns, rows = _grid_for(walls)
    side = 3.0
    plan_walls, openings = [], []

    def wall(name, start, end, outer):
        plan_walls.append({"id": name, "from": start, "to": end, "thickness": 0.2,
                           "height": 2.7})
        if outer:
            openings.append({"id": name + "-w", "type": "window", "wall": name, "offset": 0.9,
                             "width": 1.2, "height": 1.2, "sill": 0.9})
        else:
            openings.append({"id": name + "-d", "type": "door", "wall": name, "offset": 1.0,
                             "width": 0.9, "height": 2.1})

    for r in range(rows + 1):
        for c in range(columns):
            wall(f"h{r}-{c}", [1 + c * side, 1 + r * side], [1 + (c + 1) * side, 1 + r * side],
                 r in (0, rows))
    for c in range(columns + 1):
        for r in range(rows):
            wall(f"v{c}-{r}", [1 + c * side, 1 + r * side], [1 + c * side, 1 + (r + 1) * side],
                 c in (0, columns))
    if number % 7 == 3:
        openings.append({"id": "extra-w", "type": "window", "wall": "h0-0", "offset": 1.2,
                         "width": 1.2, "height": 1.2, "sill": 0.9})
    site = {"origin": [0, 0], "cells": [int(columns * side) + 3, int(rows * side) + 3],
            "cell_size": 1.0, "max_height": 4.0}
    return {"format": "roomcad-plan", "version": 1, "units": "m", "site": site,
            "walls": plan_walls, "openings": openings}


def write_grid_plans(folder, count, smallest=20, largest=200, per_folder=100):
    """Writes `count` plans of `smallest` to `largest` walls, `per_folder` in each subfolder
    (so that outputs mirror folders). @return their paths"""
    paths = []
    for number in range(count):
        walls = smallest + (number * 37) % (largest - smallest + 1)
        path = folder / f"set{number // per_folder:03d}" / f"plan{number:05d}.json"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(grid_plan(walls, number)))
        paths.append(path)
    return paths
