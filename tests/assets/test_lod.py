"""The level-of-detail set: every asset has one, built by the asset pipeline, differing only in its visuals."""

from __future__ import annotations

import re

import numpy as np
import pytest

from luminous_sim.assets import geometry as g
from luminous_sim.assets.catalog import Catalog
from luminous_sim.assets.lod import LOD_SUFFIX, decimate

CATALOG = Catalog.load(include_user=False)


def _without_lod_names(text: str) -> str:
    return text.replace(f"{LOD_SUFFIX}.obj", ".obj")


@pytest.mark.parametrize("asset_id", [e.id for e in CATALOG])
def test_every_asset_has_a_lod_set_differing_only_in_visual_meshes(asset_id):
    """Same links, joints, inertia, collision meshes, materials and visual order (state visuals keep their
    index); only visual mesh files may differ, and each LOD mesh is a listed file with fewer triangles."""
    entry = CATALOG.get(asset_id)
    assert entry.lod_urdf and entry.lod_urdf in entry.files
    full = entry.urdf_path.read_text()
    lod = entry.urdf_for(True).read_text()
    assert _without_lod_names(lod) == full
    for name in re.findall(r'filename="([^"]+)"', lod):
        assert f"{entry.urdf_path.parent.relative_to(entry.root)}/{name}" in entry.files
        if name.endswith(f"{LOD_SUFFIX}.obj"):
            lod_faces = (entry.urdf_path.parent / name).read_text().count("\nf ")
            full_faces = (entry.urdf_path.parent / name.replace(LOD_SUFFIX, "")).read_text().count("\nf ")
            assert 0 < lod_faces < full_faces, name
        else:
            assert "collision" in name or f'filename="{name}"' in full
    assert 0 < entry.lod_visual_triangles <= entry.visual_triangles


def test_the_lod_set_is_leaner_over_the_library():
    full = sum(e.visual_triangles for e in CATALOG)
    lod = sum(e.lod_visual_triangles for e in CATALOG)
    assert lod < 0.8 * full, f"LOD keeps {lod / full:.0%} of the library's visual triangles"


def test_decimate_keeps_simple_parts_and_is_deterministic():
    assert decimate(g.box((1, 1, 1))) is None  # 12 triangles: nothing to remove
    boxes = g.box((1, 1, 1)).copy()
    import trimesh

    many = trimesh.util.concatenate([boxes.copy().apply_translation((2 * i, 0, 0)) for i in range(20)])
    assert decimate(many) is None, "a mesh of boxes is 20 simple parts: none is collapsed"
    sphere = trimesh.creation.icosphere(subdivisions=3)
    first, again = decimate(sphere), decimate(sphere)
    assert first is not None and len(first.faces) < 0.5 * len(sphere.faces)
    assert np.array_equal(first.vertices, again.vertices) and np.array_equal(first.faces, again.faces)
    assert first.is_watertight and abs(first.volume - sphere.volume) < 0.1 * sphere.volume
