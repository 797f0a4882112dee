"""The meshes of a posed scene: each body's visual meshes with their colours and its convex collision parts,
read from the asset's URDF (mesh files and origins) and placed where the world has the links now.

Every format writes the same parts: an object is a frame at its base link's world pose, and its parts are
given in that frame (a door's panel where the door is now, relative to the fridge's body)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import trimesh

from luminous_sim.assets.objio import read_collision_obj
from luminous_sim.errors import AssetError
from luminous_sim.world.posed import PosedLink, PosedObject, Quat, StructureBox, Vec3

RGBA = tuple[float, float, float, float]


@dataclass(frozen=True)
class UrdfLink:
    """One link's meshes as the URDF lists them: (file, origin in the link frame), visuals in URDF order."""

    visuals: tuple[tuple[Path, np.ndarray], ...]
    collisions: tuple[tuple[Path, np.ndarray], ...]


@dataclass(frozen=True)
class VisualPart:
    """A visual mesh of a body in the body's (base link) frame, with the colour it is drawn with now."""

    name: str
    """`<link>_<index>`, unique within the body."""
    link: str
    mesh: trimesh.Trimesh
    rgba: RGBA


@dataclass(frozen=True)
class CollisionPart:
    """The convex hulls of one link, in that link's own frame (at the body's scale)."""

    link: str
    hulls: tuple[trimesh.Trimesh, ...]


def pose_matrix(position: Vec3, orientation: Quat) -> np.ndarray:
    """4x4 homogeneous matrix of a position and an (x, y, z, w) quaternion."""
    x, y, z, w = orientation
    m = np.eye(4)
    m[:3, :3] = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                 [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                 [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    m[:3, 3] = position
    return m


def link_matrix(link: PosedLink) -> np.ndarray:
    """The link frame in the world."""
    return pose_matrix(link.position, link.orientation)


def object_matrix(obj: PosedObject) -> np.ndarray:
    """The body's frame (its base link) in the world."""
    return link_matrix(obj.links[0])


def box_matrix(box: StructureBox) -> np.ndarray:
    """A structure box's frame in the world (its centre)."""
    return pose_matrix(box.center, box.orientation)


def _origin(elem: ET.Element | None) -> np.ndarray:
    m = np.eye(4)
    if elem is None:
        return m
    xyz = [float(v) for v in elem.get("xyz", "0 0 0").split()]
    r, p, y = (float(v) for v in elem.get("rpy", "0 0 0").split())
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    m[:3, :3] = [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                 [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                 [-sp, cp * sr, cp * cr]]
    m[:3, 3] = xyz
    return m


def _meshes(link: ET.Element, tag: str, folder: Path) -> tuple[tuple[Path, np.ndarray], ...]:
    out = []
    for elem in link.findall(tag):
        mesh = elem.find("geometry/mesh")
        if mesh is None or mesh.get("filename") is None:
            continue
        out.append((folder / str(mesh.get("filename")), _origin(elem.find("origin"))))
    return tuple(out)


@cache
def read_urdf(path: Path) -> dict[str, UrdfLink]:
    """Each link's visual and collision meshes (files and origins) in one of the asset library's URDFs."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as exc:
        raise AssetError(f"{path}: cannot read the asset's URDF ({exc})") from exc
    folder = path.parent
    return {str(link.get("name")): UrdfLink(_meshes(link, "visual", folder), _meshes(link, "collision", folder))
            for link in root.findall("link")}


@cache
def _visual_mesh(path: Path) -> trimesh.Trimesh:
    mesh = trimesh.load(str(path), force="mesh", process=False)
    if not isinstance(mesh, trimesh.Trimesh):
        raise AssetError(f"{path}: not a triangle mesh")
    return mesh


@cache
def _hulls(path: Path) -> tuple[trimesh.Trimesh, ...]:
    return tuple(read_collision_obj(path.read_text()))


def _scaled(origin: np.ndarray, scale: float) -> np.ndarray:
    """A mesh's origin in the link frame with the body's global scaling: the mesh and the offset grow."""
    m = origin.copy()
    m[:3, :3] = m[:3, :3] * scale
    m[:3, 3] = m[:3, 3] * scale
    return m


def visual_parts(obj: PosedObject, hidden: bool = False) -> list[VisualPart]:
    """The body's visual meshes in its own frame, coloured as drawn now; state visuals that are hidden now
    (a lamp's glow when it is off, a stain on a clean plate) are left out unless `hidden`."""
    urdf = read_urdf(obj.urdf)
    inv_base = np.linalg.inv(object_matrix(obj))
    out = []
    for link in obj.links:
        meshes = urdf.get(link.name)
        if meshes is None:
            continue
        to_base = inv_base @ link_matrix(link)
        for index, (path, origin) in enumerate(meshes.visuals):
            rgba = obj.colours.get((link.name, index), (0.8, 0.8, 0.8, 1.0))
            if rgba[3] <= 0.0 and not hidden:
                continue
            mesh = _visual_mesh(path).copy()
            mesh.apply_transform(to_base @ _scaled(origin, obj.scale))
            out.append(VisualPart(f"{link.name}_{index}", link.name, mesh, rgba))
    return out


def collision_parts(obj: PosedObject) -> list[CollisionPart]:
    """The body's convex collision parts, per link, in each link's own frame (the same hulls PyBullet
    collides: coacd's decomposition)."""
    urdf = read_urdf(obj.urdf)
    out = []
    for link in obj.links:
        meshes = urdf.get(link.name)
        if meshes is None:
            continue
        hulls = []
        for path, origin in meshes.collisions:
            for hull in _hulls(path):
                h = hull.copy()
                h.apply_transform(_scaled(origin, obj.scale))
                hulls.append(h)
        out.append(CollisionPart(link.name, tuple(hulls)))
    return out


def box_mesh(box: StructureBox) -> trimesh.Trimesh:
    """A structure box as a mesh in its own frame (centred)."""
    return trimesh.creation.box(extents=box.size)
