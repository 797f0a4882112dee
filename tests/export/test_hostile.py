"""Hostile input to `luminous export`: scene files with NaN, infinite or huge poses, zero scales, duplicate
ids or missing parents end in one line (exit 2) and write nothing (a 1e308 pose used to write an MJCF full
of NaN vertices with exit 0); a posed world that is not finite is refused; USD is written atomically like
glb and MJCF (a failure or a kill mid-write keeps the previous file)."""

from __future__ import annotations

import dataclasses
import json
import math
import re
from pathlib import Path

import pytest

from luminous_sim.cli.main import main
from luminous_sim.export import ExportError, check_posed, write
from luminous_sim.scene import Scene

CASES = {
    "nan position": ("position", [math.nan, 1.0, 0.0], "position: expected 3 finite numbers"),
    "1e308 position": ("position", [1e308, 1.0, 0.0], "position: expected 3 finite numbers"),
    "inf yaw": ("yaw", math.inf, "yaw: expected a finite number"),
    "zero scale": ("scale", 0.0, "scale: expected a number in"),
    "missing parent": ("parent", "Nope|0", "parent: no object 'Nope|0'"),
}


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("fmt", ["mjcf", "glb"])
def test_a_hostile_scene_exports_nothing_and_says_why(case: str, fmt: str, kitchen: Scene, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    field, value, needle = CASES[case]
    doc = json.loads(kitchen.to_json())
    victim = doc["objects"][3]
    victim[field] = value
    (tmp_path / "scene").mkdir()
    (tmp_path / "scene" / "scene.json").write_text(json.dumps(doc))
    out = tmp_path / ("x.xml" if fmt == "mjcf" else "x.glb")
    assert main(["export", str(tmp_path / "scene"), "--format", fmt, "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert f"scene.json: object {victim['id']!r}: {needle}" in err, err
    assert not out.exists()


def test_duplicate_ids_are_refused(kitchen: Scene, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    doc = json.loads(kitchen.to_json())
    doc["objects"][4]["id"] = doc["objects"][5]["id"]
    (tmp_path / "scene.json").write_text(json.dumps(doc))
    assert main(["export", str(tmp_path / "scene.json"), "--format", "mjcf", "--out", str(tmp_path / "x.xml")]) == 2
    assert "id: duplicate id" in capsys.readouterr().err and not (tmp_path / "x.xml").exists()


def test_a_posed_scene_that_is_not_finite_is_refused(posed, tmp_path: Path) -> None:
    obj = posed.objects[0]
    link = dataclasses.replace(obj.links[0], position=(math.nan, 0.0, 0.0))
    bad = dataclasses.replace(posed, objects=(dataclasses.replace(obj, links=(link, *obj.links[1:])),
                                              *posed.objects[1:]))
    with pytest.raises(ExportError, match=f"{re.escape(obj.object_id)}.*pose not finite"):
        check_posed(bad)
    with pytest.raises(ExportError):
        write(bad, "mjcf", tmp_path / "x.xml")
    assert not (tmp_path / "x.xml").exists()


def test_usd_keeps_the_previous_file_when_a_write_fails(posed, tmp_path: Path, monkeypatch) -> None:
    pytest.importorskip("pxr")
    import luminous_sim.export.usd as usd

    out = tmp_path / "scene.usda"
    write(posed, "usd", out)
    before = out.read_bytes()

    def broken(*args, **kwargs):
        raise RuntimeError("killed mid-write")

    monkeypatch.setattr(usd._Writer, "mesh", broken)
    with pytest.raises(RuntimeError, match="killed mid-write"):
        write(posed, "usd", out)
    assert out.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.usda"]  # no temporary file left


def test_usd_rewrites_in_place_and_holds_a_large_seed(posed, tmp_path: Path) -> None:
    pytest.importorskip("pxr")
    from pxr import Usd

    big = dataclasses.replace(posed, seed=2**63 - 1)
    for suffix in (".usda", ".usdc"):
        out = tmp_path / f"scene{suffix}"
        write(posed, "usd", out)
        write(big, "usd", out)  # over the first one
        stage = Usd.Stage.Open(str(out))
        assert stage.GetPrimAtPath("/World").GetAttribute("luminous:seed").Get() == 2**63 - 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.usda", "scene.usdc"]
