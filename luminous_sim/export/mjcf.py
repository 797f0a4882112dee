"""MJCF for MuJoCo: the structure as static boxes; every object a body at its pose, free (a `freejoint`) unless
the scene fixes it, with its links as child bodies joined by hinges and slides at their current values, each
link's mass and inertia as PyBullet simulates them, and its convex collision parts (coacd's hulls, inlined as
convex meshes) beside its visual meshes (no contacts). One self-contained file.

Joints hold their value as PyBullet's motors do, here with a spring (`stiffness`, `springref` at the value
now) and damping; an object's own links never collide with each other (PyBullet's default, no self-collision).
`settle_check` loads the file in MuJoCo, steps it and reports how far anything moved.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from itertools import combinations
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from luminous_sim.errors import LuminousError
from luminous_sim.export.meshes import box_matrix, collision_parts, link_matrix, visual_parts
from luminous_sim.world.posed import PosedJoint, PosedLink, PosedObject, PosedScene, StructureBox

TIME_STEP = 0.002
"""MuJoCo's default step (PyBullet's is 1/240 s): MuJoCo's soft contacts are stiffer at smaller steps."""
FRICTION = "0.9 0.005 0.0001"
"""Sliding (PyBullet's lateral friction in the asset library), torsional and rolling friction."""
JOINT_STIFFNESS, JOINT_DAMPING, JOINT_FRICTION, JOINT_ARMATURE = 100.0, 2.0, 0.5, 0.01
"""A door, drawer or lid is held at its value by a spring (N m/rad or N/m) with damping: MuJoCo's stand-in for
PyBullet's position motor; friction as the URDFs' joint dynamics; armature steadies light links."""


def _fmt(values: Any) -> str:
    return " ".join(f"{float(v):.6g}" for v in np.asarray(values, dtype=float).reshape(-1))


def _wxyz(q: Any) -> str:
    """MuJoCo's quaternion order (w, x, y, z) from PyBullet's (x, y, z, w)."""
    return _fmt([q[3], q[0], q[1], q[2]])


def _quat_of(m: np.ndarray) -> str:
    q = trimesh.transformations.quaternion_from_matrix(m)  # w, x, y, z
    return _fmt(q)


def _name(text: str) -> str:
    return re.sub(r"\s", "_", text)


@dataclass(frozen=True)
class MjcfOptions:
    """What `write_mjcf` writes besides the physics: visual meshes (no contacts) and the ceiling."""

    visuals: bool = True
    ceiling: bool = True


class _Builder:
    def __init__(self, posed: PosedScene, options: MjcfOptions):
        self.posed, self.options = posed, options
        self.root = ET.Element("mujoco", model=_name(posed.room))
        ET.SubElement(self.root, "compiler", angle="radian", inertiafromgeom="false", autolimits="true")
        ET.SubElement(self.root, "option", timestep=f"{TIME_STEP:g}", gravity=f"0 0 {-posed.gravity:g}",
                      integrator="implicitfast")
        default = ET.SubElement(self.root, "default")
        ET.SubElement(default, "geom", friction=FRICTION, condim="3")
        ET.SubElement(default, "joint", stiffness=f"{JOINT_STIFFNESS:g}", damping=f"{JOINT_DAMPING:g}",
                      frictionloss=f"{JOINT_FRICTION:g}", armature=f"{JOINT_ARMATURE:g}")
        visual = ET.SubElement(default, "default", {"class": "visual"})
        ET.SubElement(visual, "geom", contype="0", conaffinity="0", group="1")
        collision = ET.SubElement(default, "default", {"class": "collision"})
        ET.SubElement(collision, "geom", group="3", rgba="0.5 0.5 0.5 1")
        self.asset = ET.SubElement(self.root, "asset")
        self.world = ET.SubElement(self.root, "worldbody")
        ET.SubElement(self.world, "light", name="sun", directional="true", pos="0 0 10", dir="0 0 -1",
                      castshadow="false")
        self.contact = ET.Element("contact")
        self.meshes: set[str] = set()
        self.materials: dict[tuple[float, ...], str] = {}

    def material(self, rgba: tuple[float, float, float, float]) -> str:
        key = tuple(round(c, 4) for c in rgba)
        if key not in self.materials:
            name = f"rgba{len(self.materials)}"
            ET.SubElement(self.asset, "material", name=name, rgba=_fmt(key))
            self.materials[key] = name
        return self.materials[key]

    def box(self, box: StructureBox) -> None:
        m = box_matrix(box)
        attrs = {"name": box.name, "type": "box", "size": _fmt(np.array(box.size) / 2), "pos": _fmt(m[:3, 3]),
                 "quat": _wxyz(box.orientation)}
        if box.visible:
            attrs["material"] = self.material(box.rgba)
        else:
            attrs["rgba"] = "1 1 1 0"
        if not box.collides:
            attrs.update(contype="0", conaffinity="0")
        ET.SubElement(self.world, "geom", attrs)

    def hull_mesh(self, obj: PosedObject, link: str, index: int, hull: trimesh.Trimesh) -> str:
        name = _name(f"{obj.asset}@{obj.scale:g}/{link}/hull{index}")
        if name not in self.meshes:
            ET.SubElement(self.asset, "mesh", name=name, vertex=_fmt(hull.vertices))
            self.meshes.add(name)
        return name

    def object(self, obj: PosedObject) -> None:
        links = {link.name: link for link in obj.links}
        children: dict[str, list[PosedJoint]] = {}
        for joint in obj.joints:
            children.setdefault(joint.parent, []).append(joint)
        hulls = {part.link: part.hulls for part in collision_parts(obj)}
        visuals: dict[str, list] = {}
        if self.options.visuals:
            for part in visual_parts(obj):
                visuals.setdefault(part.link, []).append(part)
        base_world = link_matrix(obj.links[0])
        names: list[str] = []

        def add(parent: ET.Element, link: PosedLink, joint: PosedJoint | None, parent_world: np.ndarray) -> None:
            world = link_matrix(link)
            rel = np.linalg.inv(parent_world) @ world
            name = obj.object_id if joint is None else f"{obj.object_id}/{link.name}"
            names.append(name)
            body = ET.SubElement(parent, "body", name=name, pos=_fmt(rel[:3, 3]), quat=_quat_of(rel))
            if joint is None and not obj.fixed:
                ET.SubElement(body, "freejoint", name=obj.object_id)
            elif joint is not None and joint.kind != "fixed":
                ET.SubElement(body, "joint", name=f"{obj.object_id}/{joint.name}",
                              type="hinge" if joint.kind == "revolute" else "slide", axis=_fmt(joint.axis),
                              range=_fmt([joint.lower, joint.upper]), ref=f"{joint.value:.6g}",
                              springref=f"{joint.value:.6g}")
            if link.mass > 0:
                ET.SubElement(body, "inertial", pos=_fmt(link.com_position), quat=_wxyz(link.com_orientation),
                              mass=f"{link.mass:.6g}", diaginertia=_fmt(np.maximum(link.inertia, 1e-8)))
            for i, hull in enumerate(hulls.get(link.name, ())):
                ET.SubElement(body, "geom", {"class": "collision", "type": "mesh",
                                             "mesh": self.hull_mesh(obj, link.name, i, hull),
                                             "friction": f"{link.friction:.6g} 0.005 0.0001"})
            to_link = np.linalg.inv(world) @ base_world  # visual parts are given in the body's base frame
            for part in visuals.get(link.name, ()):
                mesh_name = _name(f"{obj.object_id}/{part.name}")
                vertices = trimesh.transform_points(part.mesh.vertices, to_link)
                ET.SubElement(self.asset, "mesh", name=mesh_name, vertex=_fmt(vertices), face=_fmt(part.mesh.faces),
                              inertia="shell")
                ET.SubElement(body, "geom", {"class": "visual", "type": "mesh", "mesh": mesh_name,
                                             "material": self.material(part.rgba)})
            for child in children.get(link.name, ()):
                if child.child in links:
                    add(body, links[child.child], child, world)

        add(self.world, obj.links[0], None, np.eye(4))
        for a, b in combinations(names, 2):  # PyBullet loads URDFs without self-collision
            ET.SubElement(self.contact, "exclude", body1=a, body2=b)

    def build(self) -> ET.Element:
        for box in self.posed.structure:
            if self.options.ceiling or box.kind not in ("ceiling", "light"):
                self.box(box)
        for obj in self.posed.objects:
            self.object(obj)
        if len(self.contact):
            self.root.append(self.contact)
        return self.root


def mjcf_text(posed: PosedScene, options: MjcfOptions | None = None) -> str:
    """The posed scene as MJCF text."""
    root = _Builder(posed, options or MjcfOptions()).build()
    ET.indent(root, space=" ")
    return ET.tostring(root, encoding="unicode") + "\n"


def write_mjcf(posed: PosedScene, out: Path, options: MjcfOptions | None = None) -> None:
    """Write the posed scene to `out` as one self-contained MJCF file (meshes inlined)."""
    from luminous_sim.fileio import write_atomic

    write_atomic(Path(out), mjcf_text(posed, options))


SETTLE_XY, SETTLE_Z = 0.01, 0.02
"""The project's settle tolerance (`world.scene_builder.MOVED_XY`, `MOVED_Z`): a body moved if it slid more
than 1 cm or rose or sank more than 2 cm."""
SETTLE_ANGLE, SETTLE_SLIDE = 0.02, 0.01
"""A hinge moved if it turned more than 0.02 rad (about 1 degree), a slide if it ran more than 1 cm."""


@dataclass(frozen=True)
class SettleCheck:
    """How far MuJoCo moved the exported scene in `seconds`: the largest displacement of a free body
    (sideways, vertical) and of a joint (hinge, slide), each with the body or joint it belongs to."""

    seconds: float
    bodies: int
    joints: int
    xy: tuple[float, str]
    z: tuple[float, str]
    angle: tuple[float, str]
    slide: tuple[float, str]

    @property
    def ok(self) -> bool:
        """Nothing moved more than the stated tolerances (`SETTLE_XY`, `SETTLE_Z`, `SETTLE_ANGLE`, `SETTLE_SLIDE`)."""
        return (self.xy[0] <= SETTLE_XY and self.z[0] <= SETTLE_Z and self.angle[0] <= SETTLE_ANGLE
                and self.slide[0] <= SETTLE_SLIDE)


def _mujoco() -> Any:
    try:
        import mujoco
    except ImportError as exc:
        raise LuminousError("the MuJoCo check needs mujoco: pip install 'luminous-sim[export]' "
                            "(or pip install mujoco)") from exc
    return mujoco


def settle_check(path: Path, seconds: float = 2.0) -> SettleCheck:
    """Load an exported MJCF file with `mujoco.MjModel.from_xml_path`, step it `seconds` and measure how far
    every free body's frame and every hinge and slide moved."""
    mujoco = _mujoco()
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    kind = mujoco.mjtJoint
    free_kind, slide = int(kind.mjJNT_FREE), int(kind.mjJNT_SLIDE)
    free = [b for b in range(model.nbody) if model.body_jntnum[b] >= 1
            and int(model.jnt_type[model.body_jntadr[b]]) == free_kind]
    hinges = [j for j in range(model.njnt) if int(model.jnt_type[j]) in (int(kind.mjJNT_HINGE), slide)]
    start = data.xpos[free].copy()
    qstart = data.qpos[model.jnt_qposadr[hinges]].copy() if hinges else np.zeros(0)
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    delta = data.xpos[free] - start
    qdelta = np.abs(data.qpos[model.jnt_qposadr[hinges]] - qstart) if hinges else np.zeros(0)

    def worst(values: np.ndarray, names: list[str]) -> tuple[float, str]:
        if len(values) == 0:
            return 0.0, ""
        i = int(np.argmax(values))
        return float(values[i]), names[i]

    body_names = [model.body(b).name for b in free]
    kinds = np.array([int(model.jnt_type[j]) == slide for j in hinges], dtype=bool)
    joint_names = [model.joint(j).name for j in hinges]
    turned = [(q, n) for q, n, k in zip(qdelta, joint_names, kinds) if not k]
    slid = [(q, n) for q, n, k in zip(qdelta, joint_names, kinds) if k]
    return SettleCheck(
        seconds, len(free), len(hinges),
        worst(np.linalg.norm(delta[:, :2], axis=1), body_names), worst(np.abs(delta[:, 2]), body_names),
        worst(np.array([q for q, _ in turned]), [n for _, n in turned]),
        worst(np.array([q for q, _ in slid]), [n for _, n in slid]))
