"""Write an AssetSpec as URDF + OBJ files and return its catalog entry."""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from luminous_sim.assets.decompose import convex_hull, decompose, is_convex
from luminous_sim.assets.lod import LOD_SUFFIX, decimate
from luminous_sim.assets.materials import palette
from luminous_sim.assets.objio import collision_obj, visual_obj
from luminous_sim.assets.spec import AssetSpec, Link, Part
from luminous_sim.fileio import write_atomic
from luminous_sim.vocab import abilities

HIDDEN_BY_DEFAULT = {"on", "dirty", "open"}
"""State visuals that start hidden: objects start switched off, clean and closed."""

FRICTION = {"lateral": 0.9, "rolling": 0.002, "spinning": 0.002}


def _r(x: float) -> str:
    return f"{round(float(x), 6) + 0.0:g}"


def _sig(x: float) -> str:
    """Mass and inertia with 8 significant digits: light objects have tiny but valid moments."""
    return f"{float(x):.8g}"


def _vec(v: Any) -> str:
    return " ".join(_r(x) for x in v)


def link_origins(spec: AssetSpec) -> dict[str, np.ndarray]:
    """Each link frame's origin in the asset (base) frame with every joint at zero."""
    origins = {"base": np.zeros(3)}
    pending = list(spec.joints)
    while pending:
        for j in list(pending):
            if j.parent in origins:
                origins[j.child] = origins[j.parent] + np.asarray(j.origin, dtype=float)
                pending.remove(j)
    return origins


def _visual_groups(link: Link) -> list[tuple[str, str | None, trimesh.Trimesh]]:
    groups: dict[tuple[str, str | None], list[trimesh.Trimesh]] = {}
    for part in link.parts:
        groups.setdefault((part.slot, part.state), []).append(part.mesh)
    return [(slot, state, trimesh.util.concatenate(ms)) for (slot, state), ms in groups.items()]


def _hulls(part: Part, cache_dir: Path) -> list[trimesh.Trimesh]:
    convex = is_convex(part.mesh) if part.convex is None else part.convex
    return [convex_hull(part.mesh)] if convex else decompose(part.mesh, cache_dir)


def _inertial(hulls: list[trimesh.Trimesh], mass: float) -> tuple[np.ndarray, np.ndarray]:
    """Centre of mass and inertia tensor (about the COM) of uniform-density hulls of total `mass`."""
    vols = np.array([max(h.volume, 1e-12) for h in hulls])
    density = mass / vols.sum()
    com = sum(v * h.center_mass for v, h in zip(vols, hulls)) / vols.sum()
    inertia = np.zeros((3, 3))
    for v, h in zip(vols, hulls):
        m = v * density
        d = h.center_mass - com
        inertia += h.moment_inertia * density + m * (d @ d * np.eye(3) - np.outer(d, d))
    # PyBullet diagonalises a full tensor into a rotated inertial frame, which then rotates the reported
    # base pose; the products of inertia of these near-symmetric assets are small, so keep the diagonal.
    d = np.maximum(np.diag(inertia), 1e-9)
    for i in range(3):  # keep the triangle inequality, which PyBullet enforces by zeroing the inertia
        j, k = (i + 1) % 3, (i + 2) % 3
        d[i] = min(d[i], d[j] + d[k])
    return com, np.diag(d)


def write_asset(spec: AssetSpec, out_dir: Path, cache_dir: Path) -> dict[str, Any]:
    """Write `spec` under `out_dir/<Type>/<asset id>/` and return its catalog entry.

    Two URDFs share the links, joints, inertia and collision meshes: `<id>.urdf` with the full-detail
    visuals and `<id>.lod.urdf` with the decimated ones (`lod.decimate`; a visual too simple to decimate
    is the same file in both), visual for visual in the same order, so that state visuals keep their index.
    """
    spec.validate()
    aid = spec.asset_id
    rel_dir = Path(spec.type) / aid
    adir = out_dir / rel_dir
    xml = ['<?xml version="1.0"?>', f'<robot name="{aid}">']
    lod_xml = list(xml)
    visuals: list[dict[str, Any]] = []
    files: list[str] = []
    origins = link_origins(spec)
    bounds: list[np.ndarray] = []
    n_hulls = 0
    n_vertices = 0
    n_faces = 0
    n_lod_faces = 0
    slots: set[str] = set()
    for link in spec.links:
        hulls = [h for p in link.parts if p.collide for h in _hulls(p, cache_dir)]
        n_hulls += len(hulls)
        com, inertia = _inertial(hulls, link.mass)
        head = [
            f'  <link name="{link.name}">',
            f'    <contact><lateral_friction value="{FRICTION["lateral"]}"/>'
            f'<rolling_friction value="{FRICTION["rolling"]}"/>'
            f'<spinning_friction value="{FRICTION["spinning"]}"/></contact>',
            f'    <inertial><origin xyz="{_vec(com)}" rpy="0 0 0"/><mass value="{_sig(link.mass)}"/>'
            f'<inertia ixx="{_sig(inertia[0, 0])}" ixy="0" ixz="0" '
            f'iyy="{_sig(inertia[1, 1])}" iyz="0" izz="{_sig(inertia[2, 2])}"/></inertial>',
        ]
        xml += head
        lod_xml += head
        for index, (slot, state, mesh) in enumerate(_visual_groups(link)):
            slots.add(slot)
            name = f"{link.name}__{slot}" + (f"__{state}" if state else "")
            fname = f"{name}.obj"
            write_atomic(adir / fname, visual_obj(mesh))
            files.append(str(rel_dir / fname))
            n_vertices += len(mesh.vertices)
            n_faces += len(mesh.faces)
            lod_mesh = decimate(mesh)
            lod_fname = fname
            if lod_mesh is not None:
                lod_fname = f"{name}{LOD_SUFFIX}.obj"
                write_atomic(adir / lod_fname, visual_obj(lod_mesh))
                files.append(str(rel_dir / lod_fname))
            n_lod_faces += len(mesh.faces if lod_mesh is None else lod_mesh.faces)
            rgba = list(palette(slot)[spec.variant % len(palette(slot))])
            if state in HIDDEN_BY_DEFAULT:
                rgba[3] = 0.0
            else:
                bounds.append(mesh.bounds + origins[link.name])
            for lines, mesh_file in ((xml, fname), (lod_xml, lod_fname)):
                lines.append(
                    f'    <visual name="{name}"><origin xyz="0 0 0" rpy="0 0 0"/>'
                    f'<geometry><mesh filename="{mesh_file}"/></geometry>'
                    f'<material name="{name}"><color rgba="{_vec(rgba)}"/></material></visual>'
                )
            visuals.append({"link": link.name, "index": index, "slot": slot, "state": state})
        cname = f"{link.name}__collision.obj"
        write_atomic(adir / cname, collision_obj(hulls))
        files.append(str(rel_dir / cname))
        tail = [f'    <collision><origin xyz="0 0 0" rpy="0 0 0"/><geometry><mesh filename="{cname}"/>'
                "</geometry></collision>", "  </link>"]
        xml += tail
        lod_xml += tail
    tail = []
    for j in spec.joints:
        tail.append(f'  <joint name="{j.name}" type="{j.kind}">')
        tail.append(f'    <parent link="{j.parent}"/><child link="{j.child}"/>')
        tail.append(f'    <origin xyz="{_vec(j.origin)}" rpy="0 0 0"/>')
        if j.kind != "fixed":
            tail.append(f'    <axis xyz="{_vec(j.axis)}"/>')
            tail.append(f'    <limit lower="{_r(j.lower)}" upper="{_r(j.upper)}" effort="100" velocity="2"/>')
            tail.append('    <dynamics damping="2.0" friction="0.5"/>')
        tail.append("  </joint>")
    tail.append("</robot>")
    urdf, lod_urdf = f"{aid}.urdf", f"{aid}{LOD_SUFFIX}.urdf"
    write_atomic(adir / urdf, "\n".join(xml + tail) + "\n")
    write_atomic(adir / lod_urdf, "\n".join(lod_xml + tail) + "\n")
    files += [str(rel_dir / urdf), str(rel_dir / lod_urdf)]
    lo = np.min([b[0] for b in bounds], axis=0)
    hi = np.max([b[1] for b in bounds], axis=0)
    return {
        "id": aid,
        "type": spec.type,
        "variant": spec.variant,
        "category": spec.category,
        "description": spec.description,
        "tags": sorted(spec.tags),
        "urdf": str(rel_dir / urdf),
        "lod_urdf": str(rel_dir / lod_urdf),
        "files": sorted(files),
        "bbox_min": [round(float(x), 4) for x in lo],
        "bbox_max": [round(float(x), 4) for x in hi],
        "dims": [round(float(x), 4) for x in hi - lo],
        "mass": round(sum(link.mass for link in spec.links), 4),
        "abilities": abilities(spec.type).as_dict(),
        "links": [link.name for link in spec.links],
        "link_origins": {k: [round(float(x), 5) for x in v] for k, v in origins.items()},
        "joints": [_rounded(asdict(j)) for j in spec.joints],
        "regions": [_rounded(asdict(r)) for r in spec.regions],
        "visuals": visuals,
        "palettes": {s: [list(c) for c in palette(s)] for s in sorted(slots)},
        "slices": _rounded(asdict(spec.slices)) if spec.slices else None,
        "anchors": [_rounded(asdict(a)) for a in spec.anchors],
        "collision_hulls": n_hulls,
        "visual_vertices": n_vertices,
        "visual_triangles": n_faces,
        "lod_visual_triangles": n_lod_faces,
    }


def _rounded(obj: Any) -> Any:
    if isinstance(obj, float):
        return round(obj, 5) + 0.0
    if isinstance(obj, (list, tuple)):
        return [_rounded(x) for x in obj]
    if isinstance(obj, dict):
        return {k: _rounded(v) for k, v in obj.items()}
    return obj
