"""The world as it is, read out for export: every body's links where PyBullet has them now, its joints at
their values, its colours and state, and the room's structure boxes. Plain values, no PyBullet handles, so
that `luminous_sim.export` can write glTF, USD and MJCF without importing pybullet."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from luminous_sim.world.asset_loader import LoadedAsset, base_link_pose
from luminous_sim.world.client import GRAVITY, TIME_STEP, body_aabb

if TYPE_CHECKING:
    from luminous_sim.world.world import World

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
"""x, y, z, w (PyBullet's order)."""


@dataclass(frozen=True)
class PosedLink:
    """One link of a body: its URDF link frame in the world, and its dynamics as PyBullet simulates them."""

    name: str
    position: Vec3
    orientation: Quat
    mass: float
    inertia: Vec3
    """Principal moments (kg m^2) in the inertial frame."""
    com_position: Vec3
    """The inertial frame relative to the link frame."""
    com_orientation: Quat
    friction: float


@dataclass(frozen=True)
class PosedJoint:
    """A joint of a body, with its value now (rad or m; 0 for a fixed joint)."""

    name: str
    kind: Literal["revolute", "prismatic", "fixed"]
    role: str
    """door, drawer, lid or fixed."""
    parent: str
    child: str
    origin: Vec3
    """The child link frame in the parent link frame at value 0 (no rotation: the asset builder writes none)."""
    axis: Vec3
    lower: float
    upper: float
    value: float


@dataclass(frozen=True)
class PosedObject:
    """One body of the world now: an object, or a slice of a sliced one."""

    object_id: str
    object_type: str
    asset: str
    urdf: Path
    """The full-detail URDF (meshes and their origins; paths relative to its folder)."""
    scale: float
    """The URDF's meshes and origins are loaded this many times larger."""
    fixed: bool
    states: dict[str, Any]
    """AI2-THOR-style states now (isOpen, isToggled, isDirty, isSliced, temperature, ..., parentReceptacle)."""
    links: tuple[PosedLink, ...]
    joints: tuple[PosedJoint, ...]
    colours: dict[tuple[str, int], tuple[float, float, float, float]]
    """RGBA of each (link, visual index) as drawn now: alpha 0 for a state visual that is hidden."""
    aabb: tuple[Vec3, Vec3]
    """World-axis bounds of the body's collision shapes, as PyBullet has them (with its 2 mm-ish margin)."""


@dataclass(frozen=True)
class StructureBox:
    """A box of the room's structure: a floor slab, a wall piece, the ceiling or its light."""

    name: str
    kind: Literal["floor", "wall", "ceiling", "light"]
    center: Vec3
    size: Vec3
    """Full extents along the box's own axes."""
    orientation: Quat
    rgba: tuple[float, float, float, float]
    collides: bool
    visible: bool


@dataclass(frozen=True)
class PosedScene:
    """Everything an exporter needs: the bodies now and the structure."""

    room: str
    seed: int
    objects: tuple[PosedObject, ...]
    structure: tuple[StructureBox, ...]
    gravity: float
    time_step: float


def _v(x: Any) -> Vec3:
    return (float(x[0]), float(x[1]), float(x[2]))


def _q(x: Any) -> Quat:
    return (float(x[0]), float(x[1]), float(x[2]), float(x[3]))


def _links(world: World, loaded: LoadedAsset) -> tuple[PosedLink, ...]:
    c = world.client
    out = []
    for name, index in sorted(loaded.link_index.items(), key=lambda kv: kv[1]):
        if index == -1:
            pos, orn = base_link_pose(c, loaded.body)
        else:
            pos, orn = c.getLinkState(loaded.body, index, computeForwardKinematics=True)[4:6]
        info = c.getDynamicsInfo(loaded.body, index)
        out.append(PosedLink(name, _v(pos), _q(orn), float(info[0]), _v(info[2]), _v(info[3]), _q(info[4]),
                             float(info[1])))
    return tuple(out)


def _joints(world: World, loaded: LoadedAsset) -> tuple[PosedJoint, ...]:
    out = []
    for j in loaded.entry.joints:
        index = loaded.joint_index.get(j["name"])
        moving = index is not None and j["kind"] != "fixed"
        value = float(world.client.getJointState(loaded.body, index)[0]) if moving else 0.0
        out.append(PosedJoint(j["name"], j["kind"], j["role"], j["parent"], j["child"], _v(j["origin"]), _v(j["axis"]),
                              float(j.get("lower", 0.0)), float(j.get("upper", 0.0)), value))
    return tuple(out)


def _states(world: World, oid: str) -> dict[str, Any]:
    st = world.interactions.state.objects.get(oid)
    if st is None:
        return {}
    return {"isOpen": st.isOpen, "isToggled": st.isToggled, "isDirty": st.isDirty, "isSliced": st.isSliced,
            "temperature": st.temperature, "isCooked": st.isCooked, "isFilledWithLiquid": st.isFilledWithLiquid,
            "isPickedUp": st.isPickedUp, "parentReceptacle": st.parent or ""}


def _object_type(world: World, oid: str, loaded: LoadedAsset) -> str:
    st = world.interactions.state.objects.get(oid)
    return st.object_type if st is not None else loaded.entry.type


def _structure(world: World) -> tuple[StructureBox, ...]:
    c = world.client
    built = world.built
    outdoors = set(built.outdoors)
    overhead = [b for b in built.overhead if b not in outdoors]
    named: list[tuple[str, Literal["floor", "wall", "ceiling", "light"], int, bool]] = \
        [("floor", "floor", built.floor, False)]
    named += [(f"floor#{i}", "floor", b, True) for i, b in enumerate(built.slabs)]
    named += [(f"wall#{i}", "wall", b, True) for i, b in enumerate(built.walls)]
    named += [(f"ceiling#{i}", "ceiling", b, True) for i, b in enumerate(overhead[:-1])]
    named += [("light", "light", b, True) for b in overhead[-1:]]
    out = []
    for name, kind, body, visible in named:
        shape = c.getVisualShapeData(body)[0]
        pos, orn = c.getBasePositionAndOrientation(body)
        collides = bool(c.getCollisionShapeData(body, -1))
        rgba = (float(shape[7][0]), float(shape[7][1]), float(shape[7][2]), 1.0 if visible else 0.0)
        out.append(StructureBox(name, kind, _v(pos), _v(shape[3]), _q(orn), rgba, collides, visible))
    return tuple(out)


def posed_scene(world: World) -> PosedScene:
    """Read the world as it is now: bodies (slices in place of a sliced object, doors at their angles, what
    the agent holds where it floats), their states and colours, and the structure (the hidden floor under the
    slabs has `visible` False; the ceiling and light are visual only, `collides` False, when painted last)."""
    fixed = {o.id for o in world.scene.objects if o.fixed}
    objects = []
    for oid in sorted(world.built.objects):
        loaded = world.built.objects[oid]
        lo, hi = body_aabb(world.client, loaded.body)
        objects.append(PosedObject(
            oid, _object_type(world, oid, loaded), loaded.entry.id, loaded.entry.urdf_path, float(loaded.entry.scale),
            oid in fixed, _states(world, oid),
            _links(world, loaded), _joints(world, loaded),
            {key: (float(rgb[0]), float(rgb[1]), float(rgb[2]), float(loaded.alphas.get(key, rgb[3])))
             for key, rgb in loaded.colors.items()},
            (_v(lo), _v(hi))))
    scene = world.scene
    return PosedScene(scene.room.name, scene.seed, tuple(objects), _structure(world), abs(GRAVITY), TIME_STEP)
