"""`export()` and `luminous export`: a scene folder or a live World, each format, the errors a user meets
(one line, exit status 2), and a small house."""

from __future__ import annotations

from pathlib import Path

import pytest
import trimesh

from luminous_sim.cli.main import main
from luminous_sim.export import ExportError, export
from luminous_sim.scene import Scene
from tests.houses.test_house_scene import SMALL as SMALL_HOUSE


def test_a_live_world_exports_as_it_is_now(kitchen: Scene, tmp_path: Path) -> None:
    from luminous_sim.world import World
    from luminous_sim.world.posed import posed_scene

    with World(kitchen) as world:
        fridge = next(o.id for o in kitchen.objects if o.type == "Fridge")
        assert not next(o for o in posed_scene(world).objects if o.object_id == fridge).states["isOpen"]
        pose = world.view().interaction_pose(fridge)
        assert pose is not None
        world.set_start(pose)
        assert world.step("OpenObject", objectId=fridge).success
        result = export(world, "glb", tmp_path / "open.glb")
        door = next(j for o in posed_scene(world).objects if o.object_id == fridge for j in o.joints)
    assert door.value == pytest.approx(door.upper, abs=1e-3)
    assert fridge in trimesh.load(str(result.path)).graph.nodes


def test_cli_exports_a_scene_folder_with_its_states(changed: Scene, changed_dir: Path, tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "k.glb"
    assert main(["export", str(changed_dir), "--format", "glb", "--out", str(out), "--no-ceiling"]) == 0
    assert f"wrote {out} (glb, " in capsys.readouterr().out
    apple = next(o for o in changed.objects if o.type == "Apple")
    bodies = {n for n in trimesh.load(str(out)).graph.nodes if "|" in n and "/" not in n}
    slices = {n for n in bodies if n.startswith(f"{apple.id}|AppleSliced_")}
    assert len(slices) >= 2 and apple.id not in bodies
    assert bodies == {o.id for o in changed.objects if o.id != apple.id} | slices


def test_cli_mjcf_with_mujoco_check(changed_dir: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("mujoco")
    out = tmp_path / "k.xml"
    assert main(["export", str(changed_dir), "--format", "mjcf", "--out", str(out), "--check"]) == 0
    text = capsys.readouterr().out
    assert f"wrote {out} (mjcf," in text and text.rstrip().endswith(": ok")


def test_cli_errors_are_one_line_with_status_2(changed_dir: Path, tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["export", str(tmp_path / "nowhere"), "--format", "glb", "--out", str(tmp_path / "x.glb")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "nowhere: does not exist" in err
    assert main(["export", str(changed_dir), "--format", "glb", "--out", str(tmp_path / "x.xml")]) == 2
    assert "a glb file ends in .glb" in capsys.readouterr().err
    (tmp_path / "bad").mkdir()
    (tmp_path / "bad" / "scene.json").write_text("{}")
    assert main(["export", str(tmp_path / "bad"), "--format", "glb", "--out", str(tmp_path / "x.glb")]) == 2
    assert "not a valid scene file" in capsys.readouterr().err
    for bad in (["--format", "obj", "--out", "x.glb"], ["--format", "glb", "--out", "x.obj"]):
        with pytest.raises(SystemExit) as exc:
            main(["export", str(changed_dir), *bad])
        assert exc.value.code == 2


def test_unknown_format_from_python(changed_dir: Path, tmp_path: Path) -> None:
    with pytest.raises(ExportError, match="unknown export format 'obj'"):
        export(changed_dir, "obj", tmp_path / "x.obj")


def test_a_small_house_exports_and_stays_put_in_mujoco(tmp_path: Path) -> None:
    mujoco_check = pytest.importorskip("luminous_sim.export.mjcf")
    pytest.importorskip("mujoco")
    from luminous_sim import cdf
    from luminous_sim.cssg import generate_house

    house = generate_house(cdf.loads(SMALL_HOUSE), seed=0).scene
    glb = export(house, "glb", tmp_path / "house.glb")
    nodes = trimesh.load(str(glb.path)).graph.nodes
    assert {o.id for o in house.objects} <= set(nodes)
    xml = export(house, "mjcf", tmp_path / "house.xml")
    check = mujoco_check.settle_check(xml.path)
    assert check.ok, check
