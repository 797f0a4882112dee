"""`luminous import-layout` and `luminous export-layout`."""

from __future__ import annotations

import json

from luminous_sim.cli.main import main
from tests.layouts.helpers import ATISS, FRONT, MODEL_INFO


def test_import_front_writes_the_generate_outputs_and_the_repair_report(tmp_path, capsys):
    out = tmp_path / "k"
    code = main(["import-layout", str(FRONT), "--format", "front", "--model-info", str(MODEL_INFO), "--out", str(out),
                 "--require", "Apple"])
    assert code == 0, capsys.readouterr().err
    assert {p.name for p in out.iterdir()} == {"scene.json", "report.json", "top_down.png", "egocentric.png",
                                               "repair_report.json", "layout.json"}
    repair = json.loads((out / "repair_report.json").read_text())
    assert repair["accepted"] and {r["action"] for r in repair["repairs"]} == {"moved", "placed"}
    report = json.loads((out / "report.json").read_text())
    assert report["layout"]["ok"] and report["physics"]["ok"]
    measures = report["measures"]  # the field's scene measures (docs/scene_measures.md), collisions with physics
    assert 0.0 <= measures["walkable_rate"] <= 1.0 and measures["collision"]["objects"] > 0
    assert measures["collision"]["rate"] == len(measures["collision"]["colliding"]) / measures["collision"]["objects"]
    assert any(o["type"] == "Apple" for o in json.loads((out / "scene.json").read_text())["objects"])


def test_export_then_import_gives_the_same_scene(tmp_path, capsys):
    assert main(["generate", "--room-type", "Bedroom", "--seed", "2", "--out", str(tmp_path / "g"),
                 "--no-physics"]) == 0
    assert main(["export-layout", str(tmp_path / "g" / "scene.json"), "--out", str(tmp_path / "l.json")]) == 0
    assert main(["import-layout", str(tmp_path / "l.json"), "--format", "luminous", "--out", str(tmp_path / "b"),
                 "--no-physics"]) == 0
    assert (tmp_path / "b" / "scene.json").read_bytes() == (tmp_path / "g" / "scene.json").read_bytes()


def test_malformed_input_is_exit_2_naming_file_and_field(tmp_path, capsys):
    bad = json.loads(ATISS.read_text())
    bad["angles"] = [[0.0], ["x"]]
    path = tmp_path / "boxes.json"
    path.write_text(json.dumps(bad))
    code = main(["import-layout", str(path), "--format", "atiss", "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and f"{path}: angles" in err
    assert not (tmp_path / "o").exists()
    code = main(["import-layout", str(FRONT), "--format", "luminous", "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err
    assert code == 2 and str(FRONT) in err and "room: required key is missing" in err


def test_a_rejected_layout_is_exit_2_with_its_repair_report(tmp_path, capsys):
    room = {"name": "tiny", "room_type": "Bedroom", "outline": [[0, 0], [2.4, 0], [2.4, 2.4], [0, 2.4]]}
    beds = [{"id": f"bed{i}", "category": "double bed", "size": [1.6, 2.1, 0.9], "position": [1.2, 1.2, 0.45]}
            for i in range(2)]
    path = tmp_path / "l.json"
    path.write_text(json.dumps({"room": room, "objects": beds}))
    code = main(["import-layout", str(path), "--format", "luminous", "--out", str(tmp_path / "o"), "--no-physics"])
    err = capsys.readouterr().err
    assert code == 2 and "layout rejected: bed1 (Bed): overlaps bed0" in err
    assert not json.loads((tmp_path / "o" / "repair_report.json").read_text())["accepted"]
    assert not (tmp_path / "o" / "scene.json").exists()
