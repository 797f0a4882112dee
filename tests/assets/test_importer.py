"""`luminous assets import`: a user's mesh becomes a loadable catalog asset; bad input is a clear error."""

from __future__ import annotations

import json

import numpy as np
import pytest
import trimesh

from luminous_sim.assets.catalog import Catalog
from luminous_sim.assets.importer import import_mesh
from luminous_sim.cli.main import main
from luminous_sim.errors import AssetError, VocabularyError
from tests.assets.physics_checks import drop_and_settle


@pytest.fixture()
def user_root(tmp_path, monkeypatch):
    root = tmp_path / "user_assets"
    monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(root))
    return root


def _vase_glb(path):
    """A y-up, centimetre-scale vessel, as many downloaded models are."""
    prof = [(0, 0), (5, 0), (6, 12), (4, 20), (3.5, 20), (5.4, 12), (4.5, 0.6), (0, 0.6)]
    mesh = trimesh.creation.revolve(np.array(prof, dtype=float), sections=16)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(-np.pi / 2, [1, 0, 0]))  # z-up -> y-up
    mesh.export(path)
    return path


def test_import_glb_normalises_and_loads(user_root, tmp_path):
    src = _vase_glb(tmp_path / "vase.glb")
    result = import_mesh(src, "Vase", scale=0.01, up="y")
    assert result.asset_id == "Vase_100"
    entry = Catalog.load().get("Vase_100")
    assert entry.dims[2] == pytest.approx(0.20, abs=0.005)  # height came from the y axis
    assert entry.bbox_min[2] == pytest.approx(0.0, abs=1e-4)
    assert entry.collision_hulls > 1  # decomposed, not one hull: it has a cavity
    r = drop_and_settle(entry)
    assert r["tilt_deg"] < 12 and r["min_z"] > -0.015
    assert import_mesh(src, "Vase", scale=0.01).asset_id == "Vase_101"
    ids = [e["id"] for e in json.loads((user_root / "catalog.json").read_text())["assets"]]
    assert ids == ["Vase_100", "Vase_101"]


@pytest.mark.parametrize(
    "content,suffix,message",
    [("hello world", ".obj", "no triangles"), ("", ".stl", "could not be read|no triangles"),
     ("x", ".txt", "not a mesh file")],
)
def test_bad_files_are_clear_errors(user_root, tmp_path, content, suffix, message):
    bad = tmp_path / f"bad{suffix}"
    bad.write_text(content)
    with pytest.raises(AssetError, match=message):
        import_mesh(bad, "Vase")
    assert not (user_root / "catalog.json").exists()


def test_missing_file_unknown_type_and_absurd_scale(user_root, tmp_path):
    with pytest.raises(AssetError, match="no such file"):
        import_mesh(tmp_path / "nope.obj", "Vase")
    src = _vase_glb(tmp_path / "vase.glb")
    with pytest.raises(VocabularyError, match="did you mean Vase"):
        import_mesh(src, "Vaze")
    with pytest.raises(AssetError, match="--scale"):
        import_mesh(src, "Vase", scale=1.0)  # a 20 cm vase read as 20 m
    with pytest.raises(AssetError, match="positive"):
        import_mesh(src, "Vase", scale=-1.0)


def _tube(path):
    """A cylinder wall with both caps removed: two large holes that hole-filling cannot close."""
    tube = trimesh.creation.cylinder(0.04, 0.1, sections=12)
    tube.update_faces(np.abs(tube.face_normals[:, 2]) < 0.5)
    tube.remove_unreferenced_vertices()
    tube.export(path)
    return path


def test_open_mesh_cannot_be_a_container(user_root, tmp_path):
    with pytest.raises(AssetError, match="watertight"):
        import_mesh(_tube(tmp_path / "cup.stl"), "Cup", up="z")
    assert not (user_root / "catalog.json").exists()


def test_open_mesh_is_fine_where_it_holds_nothing(user_root, tmp_path):
    result = import_mesh(_tube(tmp_path / "vase.stl"), "Candle", up="z")
    assert Catalog.load().get(result.asset_id).dims[2] == pytest.approx(0.1, abs=0.005)


def test_cli_import_exit_codes(user_root, tmp_path, capsys):
    src = _vase_glb(tmp_path / "vase.glb")
    assert main(["assets", "import", str(src), "--type", "Vase", "--scale", "0.01"]) == 0
    assert "Vase_100" in capsys.readouterr().out
    assert main(["assets", "import", str(tmp_path / "missing.glb"), "--type", "Vase"]) == 2
    assert "no such file" in capsys.readouterr().err
