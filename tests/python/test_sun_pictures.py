# SPDX-License-Identifier: GPL-3.0-or-later
# Pictures lit by the sun (`roomcad render --sun`, Plan.render(sun=)) and the shadow study
# (`roomcad shadow-study`): the sun's direction, the sky alone at night, obstructions in
# outline, sheets and their panels, errors, determinism; and the default framing.
import json
import math

import numpy as np
import pytest

import roomcad
from conftest import EXAMPLES, read_png_rgb, run_cli

PLACE = {"latitude": 55.75, "longitude": 37.62, "utc_offset": 3}
PIXELS_PER_METRE = 10  # the top views below: 200 pixels see 20 m


def site_plan(tmp_path, walls, obstructions=(), name="site.json"):
    path = tmp_path / name
    path.write_text(json.dumps({
        "format": "roomcad-plan", "version": 2, "units": "m",
        "site": {"location": PLACE, "cells": [20, 20], "origin": [-10, -10]},
        "walls": list(walls), "openings": [], "obstructions": list(obstructions)}))
    return path


def lone_wall(tmp_path):
    """A wall 6 m long along x at y = 0, 3 m high."""
    return site_plan(tmp_path, [{"id": "w", "from": [-3, 0], "to": [3, 0], "thickness": 0.2,
                                 "height": 3}])


def top_view(exe, plan, out, *extra):
    run_cli(exe, "render", plan, "-o", out, "--width", 200, "--height", 200, "--eye", "0,0,50",
            "--target", "0,0,0", "--up", "0,1,0", "--projection", "orthographic",
            "--view-height", 20, "--grid", "off", *extra)
    return read_png_rgb(out).astype(int)


def pixel_of(x, y):
    return 100 + round(x * PIXELS_PER_METRE), 100 - round(y * PIXELS_PER_METRE)


def brightness(image, x, y):
    px, py = pixel_of(x, y)
    return image[py, px].sum()


@pytest.mark.parametrize("at", ["2026-06-21T09:00", "2026-06-21T16:00"])
def test_a_walls_shadow_falls_away_from_the_sun(roomcad_exe, tmp_path, at):
    plan = lone_wall(tmp_path)
    sun = json.loads(run_cli(roomcad_exe, "sun", plan, "--at", at, "--format", "json").stdout)
    dx, dy, _ = sun["direction"]
    across = math.hypot(dx, dy)
    away = (-dx / across * 1.2, -dy / across * 1.2)  # 1.2 m from the wall's middle
    image = top_view(roomcad_exe, plan, tmp_path / "sun.png", "--sun", at)
    # the point across the wall from it lies on a floor tile of the same shade
    shaded, lit = brightness(image, *away), brightness(image, -away[0], -away[1])
    assert shaded < 0.7 * lit, (at, shaded, lit)
    # Mirrored across the wall (the sun's y taken the wrong way) the shadow is not there (the
    # other shade of tile is 10% darker).
    assert brightness(image, away[0], -away[1]) > 0.85 * lit


def test_below_the_horizon_the_sky_alone_lights_the_picture(roomcad_exe, tmp_path):
    plan = lone_wall(tmp_path)
    night = run_cli(roomcad_exe, "render", plan, "--sun", "2026-03-21T02:00", "-o",
                    tmp_path / "night.png", "--width", 160, "--height", 120)
    assert "the sun is below the horizon at 2026-03-21 02:00:00" in night.stderr.decode()
    assert "lit by the sky alone" in night.stderr.decode()
    unshadowed = run_cli(roomcad_exe, "render", plan, "--sun", "2026-03-21T02:00", "-o",
                         tmp_path / "flat.png", "--width", 160, "--height", 120, "--shadows", "off")
    assert unshadowed.returncode == 0
    assert (tmp_path / "night.png").read_bytes() == (tmp_path / "flat.png").read_bytes()
    day = run_cli(roomcad_exe, "render", plan, "--sun", "2026-03-21T12:00", "-o",
                  tmp_path / "day.png", "--width", 160, "--height", 120)
    assert b"below the horizon" not in day.stderr
    assert read_png_rgb(tmp_path / "night.png").mean() < read_png_rgb(tmp_path / "day.png").mean()


def test_obstructions_cast_shadows_and_are_drawn_in_outline(roomcad_exe, tmp_path):
    block = {"id": "block", "outline": [[-6, 3], [-2, 3], [-2, 7], [-6, 7]], "height": 8}
    plan = site_plan(tmp_path, [{"id": "w", "from": [2, -1], "to": [6, -1], "thickness": 0.2,
                                 "height": 1}], [block])
    at = "2026-06-21T13:00"  # the sun in the south: the block's shadow falls north of it
    image = top_view(roomcad_exe, plan, tmp_path / "block.png", "--sun", at)
    bare = top_view(roomcad_exe, site_plan(tmp_path, [{"id": "w", "from": [2, -1], "to": [6, -1],
                                                       "thickness": 0.2, "height": 1}],
                                           name="bare.json"), tmp_path / "bare.png", "--sun", at)
    # inside the outline: its top (lit, were it drawn) is not; the ground under it is seen in
    # its shadow, as north of it (tiles differ in shade by a tenth)
    inside, north = pixel_of(-4, 5), pixel_of(-4, 7.5)
    assert abs(image[inside[1], inside[0]].sum() - image[north[1], north[0]].sum()) < 0.15 * image[
        north[1], north[0]].sum()
    assert brightness(image, -4, 5) < 0.5 * brightness(bare, -4, 5)
    # its edge is drawn, and its shadow lies north of it
    column = pixel_of(-4, 3)[0]
    edge_rows = range(pixel_of(-4, 3)[1] - 1, pixel_of(-4, 3)[1] + 2)
    assert min(image[r, column].sum() for r in edge_rows) < 0.5 * bare[edge_rows[1], column].sum()
    assert brightness(image, -4, 8) < 0.8 * brightness(bare, -4, 8)


def test_python_gives_the_pixels_of_the_command(roomcad_exe, tmp_path):
    plan = lone_wall(tmp_path)
    run_cli(roomcad_exe, "render", plan, "--sun", "2026-04-22T14:30", "-o", tmp_path / "cli.png",
            "--width", 240, "--height", 160)
    ours = roomcad.Plan.load(plan).render(sun="2026-04-22T14:30", width=240, height=160)
    assert np.array_equal(ours, read_png_rgb(tmp_path / "cli.png"))
    with pytest.raises(roomcad.Error, match="sun"):
        roomcad.Plan.load(plan).render(sun="2026-04-31T10:00")


@pytest.mark.parametrize("args, words", [
    (["--sun", "2026-04-31T10:00"], "--sun"),
    (["--sun", "2026-04-22T10:00", "--latitude", "95"], "latitude is 95"),
    (["--latitude", "50"], "--sun"),
])
def test_bad_sun_options_are_usage_errors(roomcad_exe, tmp_path, args, words):
    out = tmp_path / "out.png"
    done = run_cli(roomcad_exe, "render", lone_wall(tmp_path), "-o", out, *args, check=False)
    assert done.returncode == 2 and words in done.stderr.decode()
    assert not out.exists()


def test_render_sun_needs_a_place(roomcad_exe, tmp_path, source_dir):
    done = run_cli(roomcad_exe, "render", source_dir / "examples/house.json", "--sun",
                   "2026-04-22T10:00", "-o", tmp_path / "out.png", check=False)
    assert done.returncode == 2 and b"site.location" in done.stderr
    assert not (tmp_path / "out.png").exists()


def sheet_size(panels, width):
    """What render/picture_sheet.h lays out: ceil(sqrt(n)) columns, 8 px apart, captions and
    the title 11 px a line (scale 1 below 240 px)."""
    columns = math.ceil(math.sqrt(panels))
    rows = math.ceil(panels / columns)
    scale = 2 if width >= 240 else 1
    line = 11 * scale
    return 8 + rows * (width + line + 8) + line, 8 + columns * (width + 8)


def test_a_sheet_has_a_panel_per_time(roomcad_exe, tmp_path):
    plan = lone_wall(tmp_path)
    run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-03-21", "--from", "08:00", "--to",
            "18:00", "--every", 60, "--width", 96, "-o", tmp_path / "study.png")
    sheet = read_png_rgb(tmp_path / "study.png")
    assert sheet.shape[:2] == sheet_size(11, 96)
    # 4 columns of 3 rows: the twelfth place is blank paper, the eleventh is not
    height, width = sheet_size(11, 96)
    last_row_top = height - (96 + 11 + 8)
    assert (sheet[last_row_top + 10:last_row_top + 90, 8 + 3 * 104 + 10:8 + 3 * 104 + 90] == 255).all()
    assert not (sheet[last_row_top + 10:last_row_top + 90, 8 + 2 * 104 + 10:8 + 2 * 104 + 90] == 255).all()


def test_a_directory_gets_a_picture_per_time(roomcad_exe, tmp_path):
    plan = lone_wall(tmp_path)
    out = tmp_path / "study"
    run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-03-21", "--from", "05:00", "--to",
            "07:30", "--every", 45, "--width", 80, "-o", f"{out}/")
    names = sorted(p.name for p in out.iterdir())
    assert names == ["study-0500.png", "study-0545.png", "study-0630.png", "study-0715.png"]
    for name in names:
        assert read_png_rgb(out / name).shape == (80 + 11, 80, 3)
    # 05:00 in March at Moscow: before sunrise, drawn by the sky alone (no shadow: one colour
    # of ground around the wall), 07:15 after it (the wall's shadow darkens some ground)
    early, late = read_png_rgb(out / "study-0500.png"), read_png_rgb(out / "study-0715.png")
    assert len(np.unique(early[:80].reshape(-1, 3), axis=0)) < len(
        np.unique(late[:80].reshape(-1, 3), axis=0))


def test_the_default_span_is_the_suns_day(roomcad_exe, tmp_path):
    plan = lone_wall(tmp_path)
    out = tmp_path / "day"
    run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-03-21", "--width", 64, "--every",
            120, "-o", f"{out}/")
    # sunrise 06:38, sunset 18:56 local (roomcad sun): 07:00 to 18:00 every two hours
    assert sorted(p.name for p in out.iterdir()) == [
        f"study-{h:02}00.png" for h in (7, 9, 11, 13, 15, 17)]


def test_threads_do_not_change_the_sheet(roomcad_exe, tmp_path, source_dir):
    plan = tmp_path / "two.json"
    plan.write_text((source_dir / "examples/version2/two-storey.json").read_text())
    run_cli(roomcad_exe, "set", plan, "site", "location=55.75,37.62,3")
    for threads in (1, 2):
        run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-06-21", "--from", "09:00",
                "--to", "15:00", "--every", 180, "--width", 128, "--threads", threads, "-o",
                tmp_path / f"t{threads}.png")
    assert (tmp_path / "t1.png").read_bytes() == (tmp_path / "t2.png").read_bytes()
    run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-06-21", "--from", "09:00",
            "--to", "15:00", "--every", 180, "--width", 128, "--level", "ground", "-o",
            tmp_path / "ground.png")
    ground = read_png_rgb(tmp_path / "ground.png")
    assert ground.shape == read_png_rgb(tmp_path / "t1.png").shape
    assert not np.array_equal(ground, read_png_rgb(tmp_path / "t1.png"))
    missing = run_cli(roomcad_exe, "shadow-study", plan, "--date", "2026-06-21", "--level",
                      "attic", "-o", tmp_path / "attic.png", check=False)
    assert missing.returncode == 2 and b"attic" in missing.stderr
    assert not (tmp_path / "attic.png").exists()


@pytest.mark.parametrize("args, words", [
    (["--date", "2026-02-30"], "--date"),
    (["--date", "2026-03-21", "--from", "8:00"], "--from '8:00'"),
    (["--date", "2026-03-21", "--to", "25:00"], "--to '25:00'"),
    (["--date", "2026-03-21", "--from", "12:00", "--to", "11:00"], "--to 11:00 is before"),
    (["--date", "2026-03-21", "--every", "0"], "--every 0"),
    (["--date", "2026-03-21", "--every", "-5"], "--every -5"),
    (["--date", "2026-03-21", "--from", "00:00", "--to", "23:00", "--every", "5"], "at most 96"),
    (["--date", "2026-03-21", "--width", "10"], "--width"),
])
def test_bad_study_options_are_usage_errors(roomcad_exe, tmp_path, args, words):
    out = tmp_path / "study.png"
    done = run_cli(roomcad_exe, "shadow-study", lone_wall(tmp_path), *args, "-o", out,
                   check=False)
    assert done.returncode == 2 and words in done.stderr.decode(), done.stderr
    assert not out.exists()


def test_a_sheet_must_be_a_png(roomcad_exe, tmp_path):
    done = run_cli(roomcad_exe, "shadow-study", lone_wall(tmp_path), "--date", "2026-03-21",
                   "-o", tmp_path / "study.jpg", check=False)
    assert done.returncode == 2 and b"-o" in done.stderr
    assert not (tmp_path / "study.jpg").exists()


@pytest.mark.parametrize("example", EXAMPLES + sorted(EXAMPLES[0].parent.glob("version2/*.json")),
                         ids=lambda p: p.name)
def test_the_default_camera_fills_the_picture(roomcad_exe, tmp_path, example):
    """The model (every pixel not the background) spans 80% of the width or the height."""
    for width, height in ((1280, 720), (600, 900)):
        out = tmp_path / "framed.png"
        run_cli(roomcad_exe, "render", example, "-o", out, "--width", width, "--height", height,
                "--background", "#ff00ff", "--force")
        image = read_png_rgb(out)
        model = ~((image[:, :, 0] == 255) & (image[:, :, 1] == 0) & (image[:, :, 2] == 255))
        ys, xs = np.nonzero(model)
        across = (xs.max() - xs.min() + 1) / width
        down = (ys.max() - ys.min() + 1) / height
        assert max(across, down) >= 0.8, (example.name, width, height, across, down)
