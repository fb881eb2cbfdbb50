# SPDX-License-Identifier: GPL-3.0-or-later
# roomcad.Plan: reading, dicts, errors with their codes and places, edits as exact and as
# strict as the command's, objects by id.
import json

import pytest

import roomcad
from conftest import SOURCE_DIR, run_cli

HOUSE = SOURCE_DIR / "examples" / "house.json"

ROOM = {
    "version": 1,
    "units": "m",
    "site": {"origin": [0, 0], "cell_size": 1, "cells": [8, 6]},
    "walls": [
        {"id": "s", "from": [1, 1], "to": [7, 1], "thickness": 0.2, "height": 2.5},
        {"id": "e", "from": [7, 1], "to": [7, 5], "thickness": 0.2, "height": 2.5},
        {"id": "n", "from": [7, 5], "to": [1, 5], "thickness": 0.2, "height": 2.5},
        {"id": "w", "from": [1, 5], "to": [1, 1], "thickness": 0.2, "height": 2.5},
    ],
    "openings": [{"id": "d", "type": "door", "wall": "s", "offset": 2, "width": 0.9, "height": 2.1}],
}


def test_dict_round_trip_is_canonical():
    plan = roomcad.Plan.from_dict(ROOM)
    again = roomcad.Plan.from_dict(plan.to_dict())
    assert again.to_json() == plan.to_json()
    assert roomcad.Plan.from_json(plan.to_json()).to_dict() == plan.to_dict()
    assert plan.ids() == ["s", "e", "n", "w", "d"]
    assert plan.ids("door") == ["d"]
    assert plan["e"]["to"] == [7, 5]
    assert "d" in plan and "nothing" not in plan
    with pytest.raises(KeyError):
        plan["nothing"]


def test_missing_file_is_an_io_error(tmp_path):
    with pytest.raises(roomcad.Error) as caught:
        roomcad.Plan.load(tmp_path / "absent.json")
    assert caught.value.code == "io_error"
    assert "absent.json" in str(caught.value)


def test_bad_json_names_line_and_column():
    with pytest.raises(roomcad.Error) as caught:
        roomcad.Plan.from_json('{"version": 1,\n  "walls": [}')
    assert caught.value.code == "parse_error"
    assert caught.value.line == 2 and caught.value.column is not None


def test_invalid_value_is_reported_with_its_field():
    bad = json.loads(json.dumps(ROOM))
    bad["walls"][0]["thickness"] = "thick"
    with pytest.raises(roomcad.Error) as caught:
        roomcad.Plan.from_dict(bad)
    assert caught.value.code in ("invalid_value", "parse_error")
    assert caught.value.file == "<dict>"


def test_report_lists_errors_with_fixes():
    overlapping = json.loads(json.dumps(ROOM))
    overlapping["walls"].append({"id": "x", "from": [2, 1], "to": [5, 1], "thickness": 0.2, "height": 2.5})
    report = roomcad.Plan.from_dict(overlapping).validate()
    assert not report.ok
    assert report.errors and all(f.severity == "error" for f in report.errors)
    first = report.errors[0]
    assert first.code == "wall_overlap" and "x" in first.objects and first.message
    assert report.to_dict()["ok"] is False
    with pytest.raises(roomcad.Error) as caught:
        roomcad.Plan.from_dict(overlapping).validate(rules="strict")
    assert caught.value.code == "usage_error"


def test_add_set_and_remove():
    plan = roomcad.Plan.from_dict(ROOM)
    window = plan.add("window", wall="n", offset=2.5, width=1.2)
    assert window == "window-1" and plan[window]["width"] == 1.2
    plan.set("s", "height", 3.0)
    assert plan["s"]["height"] == 3
    plan.set("site", "cells", (9, 6))
    assert plan.to_dict()["site"]["cells"] == [9, 6]
    plan.remove(window)
    assert window not in plan
    with pytest.raises(roomcad.Error) as caught:
        plan.set("s", "colour", "#ff0000")
    assert caught.value.code == "usage_error" and "color" in str(caught.value)
    with pytest.raises(roomcad.Error) as caught:
        plan.add("wall", **{"from": (0, 0)})  # no `to`
    assert caught.value.code == "usage_error"


def test_edit_that_introduces_errors_is_refused_and_changes_nothing():
    plan = roomcad.Plan.from_dict(ROOM)
    before = plan.to_json()
    with pytest.raises(roomcad.Error) as caught:
        plan.add("wall", "x", **{"from": (2, 1)}, to=(5, 1), thickness=0.2, height=2.5)
    assert caught.value.code == "edit_refused"
    assert plan.to_json() == before
    with pytest.raises(roomcad.Error) as caught:
        plan.remove("s")  # the door stands in it
    assert caught.value.code == "edit_refused"
    plan.remove("s", cascade=True)
    assert plan.ids() == ["e", "n", "w"]


def test_moves_and_turns_come_back_bit_for_bit():
    plan = roomcad.Plan.from_dict(ROOM)
    before = plan.to_json()
    plan.move("e", 0.1, 0.0, force=True)
    plan.move("e", -0.1, 0.0, force=True)
    assert plan.to_json() == before
    for _ in range(4):
        plan.rotate("n", 90, force=True)
    assert plan.to_json() == before
    plan.scale("n", 2.0, about=(4, 5), force=True)
    assert plan["n"]["from"] == [10, 5] and plan["n"]["to"] == [-2, 5]


def test_plan_repr_svg_is_the_floor_plan():
    plan = roomcad.Plan.load(HOUSE)
    svg = plan._repr_svg_()
    assert svg.startswith("<svg") or svg.startswith("<?xml")
    assert svg == plan.draw()


def test_help_explains_every_parameter_of_build():
    doc = roomcad.Plan.build.__doc__
    for parameter in ("force", "parts", "threads"):
        assert parameter in doc


@pytest.mark.parametrize("call", [
    lambda p: roomcad.Plan.from_dict({"version": 1, "walls": 5}),
    lambda p: roomcad.Plan.from_json("\x00"),
    lambda p: p.render(width=0),
    lambda p: p.render(width=100000, height=100000),
    lambda p: p.render(camera="nowhere"),
    lambda p: p.render(eye=(1, 2), target=(0, 0, 0)),
    lambda p: p.draw(view="bogus"),
    lambda p: p.draw(view="camera:"),
    lambda p: p.draw(scale="huge"),
    lambda p: p.set("s", "from", object()),
    lambda p: p.set("nothing", "height", 2),
    lambda p: p.add("wall", **{"from": (float("nan"), 0)}, to=(1, 0)),
    lambda p: p.move("d", 1, 0),
    lambda p: p.scale("s", -1),
    lambda p: p.build(parts=""),
], ids=lambda call: "")
def test_hostile_calls_raise_roomcad_error(call):
    plan = roomcad.Plan.from_dict(ROOM)
    before = plan.to_json()
    with pytest.raises(roomcad.Error) as caught:
        call(plan)
    assert caught.value.code and str(caught.value)
    assert plan.to_json() == before


def test_repair_applies_the_edits_and_returns_the_commands_report():
    twice = json.loads(json.dumps(ROOM))
    twice["walls"].append({"id": "s2", "from": [4, 1], "to": [6, 1], "thickness": 0.2, "height": 2.5})
    plan = roomcad.Plan.from_dict(twice)
    assert plan.validate().to_dict()["ok"] is False
    report = plan.repair(tolerance=0.01)
    assert set(report) == {"tolerance", "before", "after", "edits", "remaining"}
    assert report["before"] == {"wall_overlap": 1}
    assert report["after"] == {}
    assert [(e["object"], e["change"], e["moves"]) for e in report["edits"]] == [("s2", "delete", 0.0)]
    assert report["edits"][0]["clears"] == [{"code": "wall_overlap", "objects": ["s", "s2"]}]
    assert "s2" not in plan
    assert plan.validate().to_dict()["ok"] is True
    assert plan.repair()["edits"] == []  # nothing left to do


def test_repair_rejects_a_bad_tolerance_and_an_unknown_code():
    plan = roomcad.Plan.from_dict(ROOM)
    with pytest.raises(roomcad.Error) as bad:
        plan.repair(tolerance=-1)
    assert bad.value.code == "invalid_value"
    with pytest.raises(roomcad.Error) as unknown:
        plan.repair(only=["wall_overlaps"])
    assert unknown.value.code == "usage_error"


def test_import_ifc_gives_the_plan_of_roomcad_import(tmp_path, roomcad_exe):
    model = SOURCE_DIR / "examples" / "ifc" / "duplex.ifc"
    run_cli(roomcad_exe, "import", model, "-o", tmp_path / "duplex.json")
    plan = roomcad.import_ifc(model)
    assert plan.to_json() == (tmp_path / "duplex.json").read_text()
    assert plan.import_warnings  # the void cabinets and roofs it leaves out
    with pytest.raises(roomcad.Error) as error:
        roomcad.import_ifc(tmp_path / "duplex.json")
    assert error.value.code == "parse_error"
