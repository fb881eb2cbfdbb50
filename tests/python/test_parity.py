# SPDX-License-Identifier: GPL-3.0-or-later
# For every example plan, the Python module and the `roomcad` command agree byte for byte:
# the validation report, the canonical JSON, the OBJ (and its .mtl), the SVG drawing and the
# rendered pixels.
import json

import numpy as np
import pytest

import roomcad
from conftest import EXAMPLES, read_png_rgb, run_cli


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_report_is_the_commands_json(roomcad_exe, path):
    cli = run_cli(roomcad_exe, "validate", "--format", "json", path, check=False)
    assert cli.returncode in (0, 1)
    report = roomcad.Plan.load(path).validate()
    assert report.to_dict() == json.loads(cli.stdout)
    assert report.to_json().encode() == cli.stdout
    assert report.ok == (cli.returncode == 0)


# The rule sets by name and a rules file: the same findings, fixes and edit commands.
@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
@pytest.mark.parametrize("rules", ["all", "rules/strict.json"])
def test_report_under_rules_is_the_commands_json(roomcad_exe, source_dir, path, rules):
    if rules.endswith(".json"):
        rules = str(source_dir / "examples" / rules)
    cli = run_cli(roomcad_exe, "validate", "--format", "json", "--rules", rules, path, check=False)
    assert cli.returncode in (0, 1)
    report = roomcad.Plan.load(path).validate(rules=rules)
    assert report.to_json().encode() == cli.stdout


def test_rule_sets_add_their_findings(source_dir):
    plan = roomcad.Plan.load(source_dir / "examples" / "house.json")
    assert len(plan.validate(rules="all").findings) > len(plan.validate().findings)


def test_rules_naming_rooms_the_plan_lacks_fail_as_the_command_does(roomcad_exe, source_dir, tmp_path):
    rules = source_dir / "examples" / "rules" / "accessible-ground-floor.json"
    plan = source_dir / "examples" / "studio.json"
    cli = run_cli(roomcad_exe, "validate", "--rules", rules, plan, check=False)
    assert cli.returncode == 2
    with pytest.raises(roomcad.Error) as caught:
        roomcad.Plan.load(plan).validate(rules=str(rules))
    assert caught.value.code == "usage_error"
    assert str(caught.value) in cli.stderr.decode()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_save_writes_the_bytes_of_fmt(roomcad_exe, path, tmp_path):
    run_cli(roomcad_exe, "fmt", path, "-o", tmp_path / "cli.json")
    roomcad.Plan.load(path).save(tmp_path / "py.json")
    assert (tmp_path / "py.json").read_bytes() == (tmp_path / "cli.json").read_bytes()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_obj_is_the_bytes_of_build(roomcad_exe, path, tmp_path):
    # The same name in two folders: the OBJ names its .mtl.
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    run_cli(roomcad_exe, "build", path, "-o", tmp_path / "cli" / "model.obj")
    roomcad.Plan.load(path).build().save(tmp_path / "py" / "model.obj")
    for name in ("model.obj", "model.mtl"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_draw_is_the_svg_of_draw(roomcad_exe, path, tmp_path):
    run_cli(roomcad_exe, "draw", path, "--view", "plan", "-o", tmp_path / "cli.svg")
    assert roomcad.Plan.load(path).draw(view="plan") == (tmp_path / "cli.svg").read_text()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_render_is_the_pixels_of_render(roomcad_exe, path, tmp_path):
    # Small frames keep the test quick; every option at the command's default otherwise.
    run_cli(roomcad_exe, "render", path, "--width", 192, "--height", 108, "-o", tmp_path / "cli.png")
    pixels = roomcad.Plan.load(path).render(width=192, height=108)
    assert pixels.shape == (108, 192, 3) and pixels.dtype == np.uint8
    assert np.array_equal(pixels, read_png_rgb(tmp_path / "cli.png"))


# The report page and the BCF archive: report.to_html() is the page of `roomcad report
# --picture off`, report.to_bcf(path) the archive of `roomcad validate --format bcf`.
@pytest.mark.parametrize("name", ["house.json", "sweethome3d/3-BedroomApartment.json"])
def test_report_page_and_bcf_are_the_commands(roomcad_exe, source_dir, tmp_path, name):
    path = str(source_dir / "examples" / name)
    report = roomcad.Plan.load(path).validate()
    run_cli(roomcad_exe, "report", path, "-o", tmp_path / "page.html", "--picture", "off",
            check=False)
    assert report.to_html() == (tmp_path / "page.html").read_text()
    assert "data:image/png;base64," in report.to_html(picture=True)
    run_cli(roomcad_exe, "validate", path, "--format", "bcf", "-o", tmp_path / "cli.bcfzip",
            check=False)
    report.to_bcf(tmp_path / "py.bcfzip")
    assert (tmp_path / "py.bcfzip").read_bytes() == (tmp_path / "cli.bcfzip").read_bytes()
