"""What a procedural builder returns: an articulated asset as links of visual parts, joints, receptacle
regions and state visuals. Pure data; the URDF writer turns it into files."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import trimesh

from luminous_sim.assets.materials import palette
from luminous_sim.vocab import check_type

Vec3 = tuple[float, float, float]
Category = Literal["furniture", "appliance", "fixture", "structure", "decor", "small"]
JointKind = Literal["revolute", "prismatic", "fixed"]
JointRole = Literal["door", "drawer", "lid", "knob", "fixed"]
RegionKind = Literal["surface", "volume"]
VisualState = Literal["on", "off", "dirty", "clean", "open", "closed"]

MIN_VARIANTS: dict[str, int] = {"furniture": 4, "appliance": 4, "small": 3, "fixture": 3, "structure": 3, "decor": 3}
"""Minimum shape variants per category (furniture >= 4, small objects >= 3)."""


@dataclass
class Part:
    """One visual piece of a link.

    Attributes:
        mesh: closed triangle mesh in the link frame.
        slot: material slot (see materials.PALETTES); colours are chosen at load time.
        collide: whether the part contributes to the collision geometry.
        convex: True if the mesh is convex (its hull is exact), False to decompose with coacd,
            None to detect.
        state: if set, the part is visible only in that object state ("on": a lit bulb, running water;
            "dirty": stains); the world shows/hides it. State parts never collide.
    """

    mesh: trimesh.Trimesh
    slot: str = "plastic"
    collide: bool = True
    convex: bool | None = None
    state: VisualState | None = None

    def __post_init__(self) -> None:
        palette(self.slot)
        if self.state is not None:
            self.collide = False


@dataclass
class Link:
    """A rigid link: its parts (in the link frame) and its mass in kg."""

    name: str
    parts: list[Part]
    mass: float


@dataclass
class Joint:
    """A URDF joint. `origin` is the child frame's origin in the parent frame; limits in rad or m."""

    name: str
    kind: JointKind
    parent: str
    child: str
    origin: Vec3
    axis: Vec3 = (0.0, 0.0, 1.0)
    lower: float = 0.0
    upper: float = 0.0
    role: JointRole = "fixed"


@dataclass
class Region:
    """Where things go. A `surface` is a rectangle whose top is at center z (size z = free height above);
    a `volume` is a box interior (drawer, fridge shelf, basin). Coordinates in the frame of `link`.
    `requires_open` names the joint that must be open to reach it."""

    name: str
    kind: RegionKind
    center: Vec3
    size: Vec3
    link: str = "base"
    requires_open: str | None = None


@dataclass
class SliceSpec:
    """How a sliceable object breaks up: `count` pieces of `type` at local poses (x, y, z, yaw)."""

    type: str
    count: int
    poses: list[tuple[float, float, float, float]]


@dataclass
class Anchor:
    """An object that comes with this asset in a scene (a Sink brings its SinkBasin and Faucet)."""

    type: str
    pose: tuple[float, float, float, float]  # x, y, z, yaw in the asset frame


@dataclass
class AssetSpec:
    """A complete procedural asset before it is written to disk."""

    type: str
    variant: int
    category: Category
    links: list[Link]
    joints: list[Joint] = field(default_factory=list)
    regions: list[Region] = field(default_factory=list)
    slices: SliceSpec | None = None
    anchors: list[Anchor] = field(default_factory=list)
    description: str = ""
    tags: list[str] = field(default_factory=list)
    """Where the variant belongs when that matters, e.g. ["kitchen"] or ["bathroom"] for sinks."""

    @property
    def asset_id(self) -> str:
        return f"{self.type}_{self.variant:02d}"

    def validate(self) -> None:
        """Raise ValueError on structural mistakes a builder can make."""
        check_type(self.type)
        names = [link.name for link in self.links]
        if not names or names[0] != "base" or len(set(names)) != len(names):
            raise ValueError(f"{self.asset_id}: links must be unique and start with 'base': {names}")
        for link in self.links:
            if not link.parts or link.mass <= 0:
                raise ValueError(f"{self.asset_id}: link {link.name} needs parts and a positive mass")
            if not any(p.collide for p in link.parts):
                raise ValueError(f"{self.asset_id}: link {link.name} has no colliding part")
        children = set()
        for j in self.joints:
            if j.parent not in names or j.child not in names or j.child == "base" or j.child in children:
                raise ValueError(f"{self.asset_id}: bad joint {j.name} ({j.parent}->{j.child})")
            children.add(j.child)
            if j.kind != "fixed" and not j.lower <= j.upper:
                raise ValueError(f"{self.asset_id}: joint {j.name} has lower > upper")
        if children != set(names[1:]):
            raise ValueError(f"{self.asset_id}: every non-base link needs exactly one parent joint")
        joint_names = {j.name for j in self.joints}
        for r in self.regions:
            if r.link not in names or (r.requires_open and r.requires_open not in joint_names):
                raise ValueError(f"{self.asset_id}: region {r.name} refers to an unknown link or joint")
        if self.slices:
            check_type(self.slices.type)
        for a in self.anchors:
            check_type(a.type)
