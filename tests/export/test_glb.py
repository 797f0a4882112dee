"""glTF binary: reloaded with trimesh, one node per body named by its objectId, each node's bounds those of
the body in the world, material colours kept."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from luminous_sim.export.glb import ROOT, STRUCTURE, Z_UP_TO_Y_UP, write_glb

BOUNDS_TOL = 0.03
"""Metres: a node's bounds are its visual meshes', the world's AABB its collision hulls' (coacd's, which
wrap the visual mesh within 2 cm on the asset library; measured largest: 2.1 cm, a microwave) plus
PyBullet's margin."""


@pytest.fixture(scope="module")
def reloaded(posed, tmp_path_factory: pytest.TempPathFactory) -> trimesh.Scene:
    out = tmp_path_factory.mktemp("glb") / "kitchen.glb"
    write_glb(posed, out)
    scene = trimesh.load(str(out))
    assert isinstance(scene, trimesh.Scene)
    return scene


def _node_bounds(scene: trimesh.Scene, node: str) -> np.ndarray:
    """World (z-up) bounds of everything under `node`."""
    back = np.linalg.inv(Z_UP_TO_Y_UP)
    pts = []
    for child in scene.graph.transforms.successors(node):
        if child == node or child not in scene.graph.nodes_geometry:
            continue
        matrix, geometry = scene.graph[child]
        pts.append(trimesh.transform_points(scene.geometry[geometry].vertices, back @ matrix))
    stacked = np.vstack(pts)
    return np.array([stacked.min(axis=0), stacked.max(axis=0)])


def test_one_node_per_body_named_by_object_id(posed, reloaded: trimesh.Scene) -> None:
    ids = {o.object_id for o in posed.objects}
    top = set(reloaded.graph.transforms.children[ROOT]) - {STRUCTURE}
    assert top == ids
    assert len(top) == len(posed.objects)
    walls = [n for n in reloaded.graph.transforms.children[STRUCTURE] if n.startswith("wall#")]
    assert len(walls) == sum(b.kind == "wall" for b in posed.structure)


def test_each_node_has_the_bounds_of_its_body(posed, reloaded: trimesh.Scene) -> None:
    worst = 0.0
    for obj in posed.objects:
        bounds = _node_bounds(reloaded, obj.object_id)
        worst = max(worst, float(np.abs(bounds - np.array(obj.aabb)).max()))
    assert worst < BOUNDS_TOL


def test_material_colours_are_kept(posed, reloaded: trimesh.Scene) -> None:
    fridge = next(o for o in posed.objects if o.object_type == "Fridge")
    want = {tuple(round(255 * c) for c in rgba) for rgba in fridge.colours.values() if rgba[3] > 0}
    got = set()
    for child in reloaded.graph.transforms.successors(fridge.object_id):
        if child in reloaded.graph.nodes_geometry:
            material = reloaded.geometry[reloaded.graph[child][1]].visual.material
            got.add(tuple(int(c) for c in material.baseColorFactor))
    assert got == want


def test_ceiling_can_be_left_out(posed, tmp_path: Path) -> None:
    out = tmp_path / "open_top.glb"
    write_glb(posed, out, ceiling=False)
    scene = trimesh.load(str(out))
    assert not any(n.startswith(("ceiling", "light")) for n in scene.graph.nodes)
