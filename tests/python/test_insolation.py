# SPDX-License-Identifier: GPL-3.0-or-later
# `roomcad insolation` against the sun's path alone: for a room with one window, the intervals
# of direct sun at the window's calculation point are computed here from python3-ephem's sun
# and the window's geometry (its reveals, and an obstruction's top edge), and agree within one
# minute. Also the insolation rule: a room that falls short gets insolation_short with a fix
# whose figure is the command's own for the plan as the fix leaves it.
import json
import math

import ephem
import pytest

from conftest import run_cli

LATITUDE, LONGITUDE, OFFSET = 55.75, 37.62, 3
DATE = "2026-04-22"
WIDTH, HEIGHT, SILL = 1.2, 1.5, 0.9


def room_plan(thickness, obstruction=None):
    """A 4 x 4 m room with a roof slab; one window in the middle of its south wall."""
    half = thickness / 2
    corners = [[0, 0], [4, 0], [4, 4], [0, 4]]
    walls = [{"id": f"w{i}", "from": corners[i], "to": corners[(i + 1) % 4],
              "thickness": thickness, "height": 3.0} for i in range(4)]
    plan = {
        "format": "roomcad-plan", "version": 2, "units": "m",
        "site": {"origin": [-60, -60], "cells": [130, 130], "cell_size": 1.0, "max_height": 30,
                 "location": {"latitude": LATITUDE, "longitude": LONGITUDE,
                              "utc_offset": OFFSET}},
        "walls": walls,
        "openings": [{"id": "south", "type": "window", "wall": "w0", "offset": 2 - WIDTH / 2,
                      "width": WIDTH, "height": HEIGHT, "sill": SILL}],
        "slabs": [{"id": "roof", "outline": [[-half, -half], [4 + half, -half],
                                             [4 + half, 4 + half], [-half, 4 + half]],
                   "top": 3.2, "thickness": 0.2}],
        "rooms": [{"id": "living", "at": [2, 2], "name": "Living room"}],
    }
    if obstruction:
        plan["obstructions"] = [obstruction]
    return plan


def expected_intervals(thickness, distance=None, height=None):
    """Seconds after local midnight when the sun reaches the point (2, t/2, SILL) through the
    window: above the horizon, within the jambs and under the lintel seen through the wall,
    and (with an obstruction) above its top edge `distance` m south of the wall's outer face."""
    observer = ephem.Observer()
    observer.lat, observer.lon = str(LATITUDE), str(LONGITUDE)
    observer.elevation, observer.pressure = 0, 0
    midnight = ephem.Date(ephem.Date(DATE.replace("-", "/")) - OFFSET * ephem.hour)

    def lit(seconds):
        observer.date = ephem.Date(midnight + seconds * ephem.second)
        sun = ephem.Sun(observer)
        if sun.alt <= 0:
            return False
        dx = math.sin(sun.az) * math.cos(sun.alt)
        dy = math.cos(sun.az) * math.cos(sun.alt)
        dz = math.sin(sun.alt)
        if dy >= 0:
            return False
        through = thickness / -dy  # ray parameter across the wall
        if abs(dx) * through >= WIDTH / 2 or dz * through >= HEIGHT:
            return False
        if distance is not None:
            reach = (thickness + distance) / -dy
            if SILL + dz * reach <= height:
                return False
        return True

    intervals, was, step = [], lit(0), 30
    start = 0 if was else None
    for k in range(1, 86400 // step + 1):
        now = lit(k * step)
        if now == was:
            continue
        a, b = (k - 1) * step, k * step
        while b - a > 0.5:
            m = (a + b) / 2
            if lit(m) == was:
                a = m
            else:
                b = m
        if now:
            start = (a + b) / 2
        else:
            intervals.append((start, (a + b) / 2))
        was = now
    if was:
        intervals.append((start, 86400))
    return intervals


def seconds_of(clock):
    h, m, s = map(int, clock.split(":"))
    return h * 3600 + m * 60 + s


def window_intervals(roomcad_exe, tmp_path, plan):
    path = tmp_path / "room.json"
    path.write_text(json.dumps(plan))
    out = json.loads(run_cli(roomcad_exe, "insolation", path, "--date", DATE, "--format",
                             "json").stdout)
    rooms = [r for r in out["rooms"] if r["room"] == "living"]
    assert len(rooms) == 1
    room = rooms[0]
    assert room["name"] == "Living room" and room["best_window"] == "south"
    window = room["windows"][0]
    assert room["continuous_hours"] == window["continuous_hours"]
    return [(seconds_of(a), seconds_of(b)) for a, b in window["intervals"]], window


def assert_agree(ours, expected):
    assert len(ours) == len(expected), (ours, expected)
    for (a, b), (c, d) in zip(ours, expected):
        assert abs(a - c) < 60 and abs(b - d) < 60, (ours, expected)


@pytest.mark.parametrize("thickness", [0.3, 0.6])  # 0.6: the reveal cuts the morning sun
def test_a_south_window_gets_the_sun_its_reveals_let_through(roomcad_exe, tmp_path, thickness):
    ours, window = window_intervals(roomcad_exe, tmp_path, room_plan(thickness))
    expected = expected_intervals(thickness)
    assert_agree(ours, expected)
    hours = sum(b - a for a, b in expected) / 3600
    assert window["total_hours"] == pytest.approx(hours, abs=1 / 60)
    if thickness == 0.6:  # narrower than the thin wall's on both ends
        thin = expected_intervals(0.3)
        assert expected[0][0] > thin[0][0] + 1800 and expected[-1][1] < thin[-1][1] - 1800


def test_an_obstruction_of_known_height_shortens_the_sun(roomcad_exe, tmp_path):
    distance, height = 10.0, 12.0  # the block hides the sun around noon
    block = {"id": "block", "outline": [[-50, -0.15 - distance - 10], [54, -0.15 - distance - 10],
                                        [54, -0.15 - distance], [-50, -0.15 - distance]],
             "height": height}
    ours, _ = window_intervals(roomcad_exe, tmp_path, room_plan(0.3, block))
    expected = expected_intervals(0.3, distance, height)
    assert_agree(ours, expected)
    assert sum(b - a for a, b in expected) < sum(b - a for a, b in expected_intervals(0.3))


def test_a_room_that_falls_short_gets_a_fix_checked_by_recomputing(roomcad_exe, tmp_path):
    # The window turned to face north: no sun on 22 April at 55.75 N; the fix proposes a window
    # on another wall, and the hours it quotes are what the command computes for that plan.
    plan = room_plan(0.3)
    plan["openings"][0]["wall"] = "w2"
    path = tmp_path / "north.json"
    path.write_text(json.dumps(plan))
    rules = tmp_path / "rules.json"
    rules.write_text(json.dumps({"rules": {"insolation_short": {
        "date": "04-22", "min_continuous_hours": 2.0, "severity": "error"}}}))
    done = run_cli(roomcad_exe, "validate", path, "--rules", rules, "--format", "json",
                   check=False)
    assert done.returncode == 1
    findings = [f for f in json.loads(done.stdout)["errors"] if f["code"] == "insolation_short"]
    assert len(findings) == 1
    finding = findings[0]
    assert finding["objects"] == ["living", "south"]
    assert "the rule asks 2 h continuous" in finding["message"]
    fix = finding["fix"]
    assert "facing S" in fix and "gives" in fix, fix
    wall = fix.split("wall '")[1].split("'")[0]
    quoted = float(fix.split("gives ")[1].split(" h continuous")[0])
    plan["openings"].append({"id": "south-sun", "type": "window", "wall": wall,
                             "offset": 2 - WIDTH / 2, "width": WIDTH, "height": HEIGHT,
                             "sill": SILL})
    path.write_text(json.dumps(plan))
    out = json.loads(run_cli(roomcad_exe, "insolation", path, "--date", DATE, "--format",
                             "json").stdout)
    living = [r for r in out["rooms"] if r["room"] == "living"][0]
    added = [w for w in living["windows"] if w["id"] == "south-sun"][0]
    assert added["continuous_hours"] == pytest.approx(quoted, abs=0.01)
    assert quoted >= 2.0


def test_the_rule_is_silent_without_a_location(roomcad_exe, tmp_path):
    plan = room_plan(0.3)
    plan["openings"][0]["wall"] = "w2"
    del plan["site"]["location"]
    path = tmp_path / "nowhere.json"
    path.write_text(json.dumps(plan))
    done = run_cli(roomcad_exe, "validate", path, "--rules", "all", "--format", "json")
    assert "insolation_short" not in done.stdout.decode()
    missing = run_cli(roomcad_exe, "insolation", path, "--date", DATE, check=False)
    assert missing.returncode == 2 and b"site.location" in missing.stderr


def test_the_module_gives_what_the_command_prints(roomcad_exe, tmp_path):
    import roomcad
    path = tmp_path / "room.json"
    path.write_text(json.dumps(room_plan(0.3)))
    printed = json.loads(run_cli(roomcad_exe, "insolation", path, "--date", DATE, "--format",
                                 "json").stdout)
    ours = roomcad.Plan.load(path).insolation(DATE)
    assert ours["date"] == printed["date"] and ours["utc_offset"] == printed["utc_offset"]
    for mine, theirs in zip(ours["rooms"], printed["rooms"], strict=True):
        assert mine["room"] == theirs["room"] and mine["best_window"] == theirs["best_window"]
        for w, v in zip(mine["windows"], theirs["windows"], strict=True):
            assert [list(i) for i in w["intervals"]] == v["intervals"]
            assert w["continuous_hours"] == pytest.approx(v["continuous_hours"], abs=1e-4)
    finding = [f for f in roomcad.Plan.load(path).validate(rules="all").warnings
               if f.code == "insolation_short"]
    assert finding == []  # a south window in Moscow gets its 1.5 h on 21 March
