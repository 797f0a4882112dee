"""USD: read back with pxr, one prim per body with its objectId, type and states as attributes, its
meshes and their materials."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

pxr = pytest.importorskip("pxr", reason="USD export needs usd-core (the export extra)")
from pxr import Usd, UsdGeom, UsdShade  # noqa: E402

from luminous_sim.export.usd import prim_name, write_usd  # noqa: E402


@pytest.fixture(scope="module", params=["usd", "usda"])
def stage(request: pytest.FixtureRequest, posed, tmp_path_factory: pytest.TempPathFactory) -> Usd.Stage:
    out = tmp_path_factory.mktemp("usd") / f"kitchen.{request.param}"
    write_usd(posed, out)
    return Usd.Stage.Open(str(out))


def _attrs(prim: Usd.Prim) -> dict:
    return {a.GetName().removeprefix("luminous:"): a.Get() for a in prim.GetAttributes()
            if a.GetName().startswith("luminous:")}


def test_one_prim_per_body_with_its_id_type_and_state(posed, stage: Usd.Stage) -> None:
    prims = stage.GetPrimAtPath("/World/Objects").GetChildren()
    assert len(prims) == len(posed.objects)
    by_id = {_attrs(p)["objectId"]: p for p in prims}
    assert set(by_id) == {o.object_id for o in posed.objects}
    for obj in posed.objects:
        attrs = _attrs(by_id[obj.object_id])
        assert attrs["type"] == obj.object_type
        assert by_id[obj.object_id].GetName() == prim_name(obj.object_id)
        for key in ("isOpen", "isSliced", "isToggled", "isDirty"):
            assert attrs[key] == obj.states[key], (obj.object_id, key)
    fridge = next(o for o in posed.objects if o.object_type == "Fridge")
    attrs = _attrs(by_id[fridge.object_id])
    assert attrs["isOpen"] is True
    door = next(j for j in fridge.joints if j.role == "door")
    assert attrs[f"joint:{door.name}"] == pytest.approx(door.value)
    assert any(_attrs(p)["type"] == "AppleSliced" and _attrs(p)["isSliced"] for p in prims)


def test_meshes_and_materials_are_there_and_posed(posed, stage: Usd.Stage) -> None:
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
    for obj in posed.objects:
        prim = stage.GetPrimAtPath(f"/World/Objects/{prim_name(obj.object_id)}")
        meshes = [c for c in prim.GetChildren() if c.IsA(UsdGeom.Mesh)]
        assert meshes, obj.object_id
        for mesh in meshes:
            assert len(UsdGeom.Mesh(mesh).GetPointsAttr().Get()) > 0
            material = UsdShade.MaterialBindingAPI(mesh).ComputeBoundMaterial()[0]
            assert material and material.GetSurfaceOutput().HasConnectedSource()
        box = cache.ComputeWorldBound(prim).ComputeAlignedRange()
        got = np.array([list(box.GetMin()), list(box.GetMax())])
        assert np.abs(got - np.array(obj.aabb)).max() < 0.03, obj.object_id  # as the glTF test: visual vs hulls
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    walls = [p for p in stage.GetPrimAtPath("/World/Structure").GetChildren() if p.GetName().startswith("wall")]
    assert len(walls) == sum(b.kind == "wall" for b in posed.structure)


def test_an_existing_file_is_replaced(posed, tmp_path: Path) -> None:
    out = tmp_path / "twice.usda"
    write_usd(posed, out)
    write_usd(posed, out)
    assert Usd.Stage.Open(str(out)).GetPrimAtPath("/World/Objects")
