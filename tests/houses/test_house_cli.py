"""`luminous generate --house`: the files of a room, for a house; bad input is one line naming what."""

from __future__ import annotations

import json
from pathlib import Path

from tests.cli.test_errors import EXAMPLES, one_line_error, run
from tests.houses.test_house_scene import SMALL


def test_generate_house_writes_the_scene_files(tmp_path: Path, capsys) -> None:
    house = tmp_path / "small.yaml"
    house.write_text(SMALL)
    code, out, err = run(["generate", "--house", str(house), "--seed", "0", "--out", str(tmp_path / "h"),
                          "--no-physics"], capsys)
    assert code == 0, err
    for name in ("scene.json", "report.json", "top_down.png", "egocentric.png"):
        assert (tmp_path / "h" / name).is_file()
    report = json.loads((tmp_path / "h" / "report.json").read_text())
    assert report["layout"]["ok"] and set(report["layout"]["rooms_reached"]) == {"kitchen", "living", "bedroom"}
    assert "kitchen (Kitchen)" in out
    scene = json.loads((tmp_path / "h" / "scene.json").read_text())
    assert [r["name"] for r in scene["room"]["house"]["rooms"]] == ["kitchen", "living", "bedroom"]


def test_generate_house_refuses_a_single_room_cdf_and_clashing_flags(tmp_path: Path, capsys) -> None:
    code, _, err = run(["generate", "--house", str(EXAMPLES / "kitchen_coffee_mug.yaml"), "--out",
                        str(tmp_path / "x")], capsys)
    assert code == 2 and one_line_error(err) and "scene.house is not set" in err
    code, _, err = run(["generate", "--house", "--room", "FloorPlan1", "--out", str(tmp_path / "y")], capsys)
    assert code == 2 and one_line_error(err) and "--house takes no --room" in err
