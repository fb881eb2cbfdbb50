# SPDX-License-Identifier: GPL-3.0-or-later
# The sun's position against an independent reader: Debian's python3-ephem (libastro, VSOP87),
# refraction off (pressure 0), topocentric at sea level, as `roomcad sun` computes it. 1,000
# random places and times over 1950-2100 at every latitude agree within 0.01 degree; sunrise,
# solar noon and sunset within a minute; the command prints the same as the module.
import datetime
import json
import math
import random

import ephem
import pytest

import roomcad
from conftest import run_cli

TOLERANCE_DEGREES = 0.01


def ephem_sun(latitude, longitude, when_utc):
    observer = ephem.Observer()
    observer.lat, observer.lon = str(latitude), str(longitude)
    observer.elevation = 0
    observer.pressure = 0  # no refraction: the geometric elevation
    observer.date = ephem.Date(when_utc)
    sun = ephem.Sun(observer)
    return math.degrees(sun.az), math.degrees(sun.alt), observer


def angle_between(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


def random_cases(count, seed=20261207):
    rng = random.Random(seed)
    start = datetime.datetime(1950, 1, 1)
    span = (datetime.datetime(2100, 12, 31) - start).total_seconds()
    for _ in range(count):
        when = start + datetime.timedelta(seconds=int(rng.uniform(0, span)))
        yield rng.uniform(-89.9, 89.9), rng.uniform(-180, 180), when


def test_positions_agree_with_ephem_on_1000_places_and_times():
    worst_azimuth = worst_elevation = 0.0
    for latitude, longitude, when in random_cases(1000):
        ours = roomcad.sun(when.strftime("%Y-%m-%dT%H:%M:%SZ"), latitude, longitude)
        azimuth, elevation, _ = ephem_sun(latitude, longitude, when)
        # Azimuth is ill-defined at the zenith: compare it scaled by the horizontal part.
        worst_azimuth = max(worst_azimuth, angle_between(ours["azimuth"], azimuth) *
                            math.cos(math.radians(elevation)))
        worst_elevation = max(worst_elevation, abs(ours["elevation"] - elevation))
        d = ours["direction"]  # north 0: +y north, +x east
        assert math.isclose(math.hypot(*d), 1.0, abs_tol=1e-12)
        assert math.degrees(math.asin(d[2])) == pytest.approx(ours["elevation"], abs=1e-9)
    assert worst_azimuth < TOLERANCE_DEGREES
    assert worst_elevation < TOLERANCE_DEGREES


def seconds_of(clock):
    h, m, s = map(int, clock.split(":"))
    return h * 3600 + m * 60 + s


@pytest.mark.parametrize("latitude, longitude, offset, date", [
    (55.75, 37.62, 3, "2026-04-22"),    # Moscow, SanPiN's date
    (51.48, 0.0, 0, "2026-03-21"),      # Greenwich, EN 17037's date
    (-33.87, 151.21, 10, "2026-06-21"),  # Sydney in winter
    (1.29, 103.85, 8, "2026-12-07"),    # Singapore
])
def test_sunrise_noon_and_sunset_agree_with_ephem(latitude, longitude, offset, date):
    ours = roomcad.sun(date + "T12:00", latitude, longitude, offset)
    observer = ephem.Observer()
    observer.lat, observer.lon = str(latitude), str(longitude)
    observer.elevation, observer.pressure, observer.horizon = 0, 0, "0"
    midnight = datetime.datetime.fromisoformat(date) - datetime.timedelta(hours=offset)
    observer.date = ephem.Date(midnight)
    local = lambda d: (ephem.Date(d).datetime() - midnight).total_seconds()
    rise = local(observer.next_rising(ephem.Sun(), use_center=True))
    transit = local(observer.next_transit(ephem.Sun()))
    setting = local(observer.next_setting(ephem.Sun(), use_center=True))
    assert abs(seconds_of(ours["sunrise"]) - rise) < 60
    assert abs(seconds_of(ours["solar_noon"]) - transit) < 60
    assert abs(seconds_of(ours["sunset"]) - setting) < 60


def test_polar_day_has_no_sunrise_or_sunset():
    ours = roomcad.sun("2026-06-21T12:00", 78.2, 15.6, 2)  # Svalbard at midsummer
    assert ours["sunrise"] is None and ours["sunset"] is None
    assert ours["elevation"] > 0


def test_the_command_prints_what_the_module_computes(roomcad_exe, tmp_path):
    at, latitude, longitude = "2026-04-22T14:30", 55.75, 37.62
    done = run_cli(roomcad_exe, "sun", "--latitude", latitude, "--longitude", longitude,
                   "--utc-offset", 3, "--at", at, "--format", "json")
    printed = json.loads(done.stdout)
    ours = roomcad.sun(at, latitude, longitude, 3)
    for key in ("azimuth", "elevation"):
        assert printed[key] == pytest.approx(ours[key], abs=1e-6)
    for key in ("sunrise", "solar_noon", "sunset"):
        assert printed[key] == ours[key]
    # A plan turned so that north is +x: the sun's direction turns with it.
    plan = tmp_path / "turned.json"
    plan.write_text(json.dumps({
        "format": "roomcad-plan", "version": 2, "units": "m",
        "site": {"location": {"latitude": latitude, "longitude": longitude, "utc_offset": 3},
                 "north": -90},
        "walls": [], "openings": []}))
    turned = json.loads(run_cli(roomcad_exe, "sun", plan, "--at", at, "--format",
                                "json").stdout)
    assert turned["direction"][0] == pytest.approx(ours["direction"][1], abs=1e-9)
    assert turned["direction"][1] == pytest.approx(-ours["direction"][0], abs=1e-9)


@pytest.mark.parametrize("args, words", [
    (["--at", "2026-04-31T10:00", "--latitude", "50", "--longitude", "0"], "not a time"),
    (["--at", "2026-04-22T10:00", "--latitude", "95", "--longitude", "0"], "latitude is 95"),
    (["--at", "2026-04-22T10:00"], "give --latitude and --longitude"),
])
def test_bad_input_is_a_usage_error(roomcad_exe, args, words):
    done = run_cli(roomcad_exe, "sun", *args, check=False)
    assert done.returncode == 2
    assert words in done.stderr.decode()
