"""MJCF: loaded by MuJoCo as written (`MjModel.from_xml_path`), the objects free bodies with their convex
parts, the furniture's doors and drawers joints at their current values, and 2 s of MuJoCo moving nothing
more than the stated tolerance."""

from __future__ import annotations

from pathlib import Path

import pytest

mujoco = pytest.importorskip("mujoco", reason="the MuJoCo check needs mujoco (the export extra)")

from luminous_sim.export.meshes import collision_parts  # noqa: E402
from luminous_sim.export.mjcf import SETTLE_XY, SETTLE_Z, settle_check, write_mjcf  # noqa: E402


@pytest.fixture(scope="module")
def xml(posed, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("mjcf") / "kitchen.xml"
    write_mjcf(posed, out)
    return out


def test_mujoco_loads_it_with_every_body_and_joint(posed, xml: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(xml))
    for obj in posed.objects:
        body = model.body(obj.object_id)
        assert model.body_jntnum[body.id] == (0 if obj.fixed else 1)
        for joint in obj.joints:
            if joint.kind == "fixed":
                continue
            j = model.joint(f"{obj.object_id}/{joint.name}")
            assert float(model.qpos0[model.jnt_qposadr[j.id]]) == pytest.approx(joint.value, abs=1e-5)
            assert tuple(model.jnt_range[j.id]) == pytest.approx((joint.lower, joint.upper), abs=1e-5)
        hulls = sum(len(part.hulls) for part in collision_parts(obj))
        collision = [g for g in range(model.ngeom) if model.geom_group[g] == 3
                     and model.body(model.geom_bodyid[g]).name.split("/")[0] == obj.object_id]
        assert len(collision) == hulls > 0, obj.object_id
        mass = sum(link.mass for link in obj.links)
        if not obj.fixed:
            assert float(model.body_subtreemass[body.id]) == pytest.approx(mass, rel=1e-4)
    fridge = next(o for o in posed.objects if o.object_type == "Fridge")
    door = next(j for j in fridge.joints if j.role == "door")
    assert door.value > 1.0  # open, and MuJoCo starts it there (qpos0 above)


def test_two_seconds_of_mujoco_move_nothing_beyond_the_tolerance(xml: Path) -> None:
    check = settle_check(xml, seconds=2.0)
    assert check.bodies > 20 and check.joints > 0
    assert check.xy[0] <= SETTLE_XY and check.z[0] <= SETTLE_Z, check
    assert check.ok, check
