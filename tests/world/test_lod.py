"""Level of detail in the world: chosen by frame size, same physics, same silhouettes, state visuals kept."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.assets.catalog import Catalog
from luminous_sim.world.asset_loader import load_asset, show_state
from luminous_sim.world.camera import render
from luminous_sim.world.client import new_client
from luminous_sim.world.config import WorldConfig
from tests.world.conftest import obj

CATALOG = Catalog.load(include_user=False)
VIEWS = 4
SIZE = 128
IOU_MIN = 0.9
"""Silhouette IoU of the LOD set against full detail, per view (128 px, 4 views around each asset). Measured
over all 419 assets: min 0.933 (BaseballBat_03), 1st percentile 0.942, median 0.994. Decimating each visual
mesh as one piece without the per-part checks of `assets.lod` gave min 0.27 (a footstool's legs collapsed):
0.9 passes every asset today with a margin and fails such a collapse."""
SAMPLE = ["BaseballBat_03", "HousePlant_02", "Footstool_02", "Towel_01", "CounterTop_02", "Mug_00", "Fridge_01",
          "TennisRacket_01", "LettuceSliced_02", "Laptop_01", "TeddyBear_02", "Bed_04"]


def _views(entry) -> list[tuple[np.ndarray, np.ndarray]]:
    lo, hi = np.array(entry.bbox_min), np.array(entry.bbox_max)
    lo[2], hi[2] = 0.0, hi[2] - entry.bbox_min[2]
    center = (lo + hi) / 2
    radius = float(np.linalg.norm(hi - lo)) / 2
    out = []
    for az in np.radians(30 + 360 / VIEWS * np.arange(VIEWS)):
        d = np.array([np.sin(az), np.cos(az), 0.6])
        out.append((center + d / np.linalg.norm(d) * 1.12 * radius / np.tan(np.radians(22)), center))
    return out


def _render_asset(entry, lod: bool, states: tuple[str, ...] = ()) -> list:
    client = new_client()
    try:
        loaded = load_asset(client, entry, (0.0, 0.0, -entry.bbox_min[2]), fixed=True, lod=lod)
        for s in states:
            show_state(client, loaded, s, True)
        return [(render(client, eye, target, width=SIZE, height=SIZE, fov=45, near=0.01, far=50), loaded.body)
                for eye, target in _views(entry)]
    finally:
        client.disconnect()


def silhouette_ious(entry) -> list[float]:
    full, lod = _render_asset(entry, False), _render_asset(entry, True)
    ious = []
    for (a, body_a), (b, body_b) in zip(full, lod, strict=True):
        ma, mb = (a.seg & 0xFFFFFF) == body_a, (b.seg & 0xFFFFFF) == body_b
        ious.append(float((ma & mb).sum() / max(1, (ma | mb).sum())))
    return ious


@pytest.mark.parametrize("asset_id", SAMPLE)
def test_lod_keeps_the_silhouette(asset_id):
    ious = silhouette_ious(CATALOG.get(asset_id))
    assert min(ious) >= IOU_MIN, f"{asset_id}: silhouette IoU {ious}"


@pytest.mark.slow
@pytest.mark.parametrize("asset_id", [e.id for e in CATALOG])
def test_lod_keeps_the_silhouette_of_every_asset(asset_id):
    ious = silhouette_ious(CATALOG.get(asset_id))
    assert min(ious) >= IOU_MIN, f"{asset_id}: silhouette IoU {ious}"


def _with_state(state: str) -> list[str]:
    return [e.id for e in CATALOG if any(v["state"] == state for v in e.visuals)]


@pytest.mark.parametrize("state", ["on", "dirty"])
def test_state_visuals_show_in_lod(state):
    """Switching a state visual on changes the LOD rendering as it changes the full-detail one."""
    for asset_id in _with_state(state)[:3]:
        entry = CATALOG.get(asset_id)
        for lod in (False, True):
            plain = _render_asset(entry, lod)
            shown = _render_asset(entry, lod, (state,))
            assert any(not np.array_equal(a.rgb, b.rgb) for (a, _), (b, _) in zip(plain, shown, strict=True)), \
                f"{asset_id} ({'LOD' if lod else 'full'}): the {state} visual does not show"


def test_world_config_picks_lod_by_frame_size():
    assert not WorldConfig().use_lod  # ALFRED's 300x300: full detail
    assert WorldConfig(width=128, height=128).use_lod and WorldConfig(width=64, height=64).use_lod
    assert not WorldConfig(width=64, height=64, lod_max_size=0).use_lod
    assert not WorldConfig(width=128, height=200).use_lod


def test_small_world_loads_lod_with_the_same_physics_and_slices_in_lod(kitchen_scene):
    from luminous_sim.world.slicing import slice_body
    from luminous_sim.world.world import World

    with World(kitchen_scene, WorldConfig(settle_steps=120)) as full, \
            World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120)) as small:
        assert all(not lo.lod for lo in full.built.objects.values())
        assert all(lo.lod for lo in small.built.objects.values())
        files = {v[4].decode() for lo in small.built.objects.values() for v in small.client.getVisualShapeData(lo.body)}
        assert any(f.endswith(".lod.obj") for f in files)
        for oid in full.built.objects:  # collision and inertia are the same files: the same settled world
            pos_a, yaw_a = full.built.pose_of(oid)
            pos_b, yaw_b = small.built.pose_of(oid)
            assert np.array_equal(pos_a, pos_b) and yaw_a == yaw_b, oid
        apple = obj(kitchen_scene, "apple")
        slice_body(small, apple, "AppleSliced")
        slices = [o for o in small.built.objects if o.startswith(apple + "|")]
        assert slices and all(small.built.objects[s].lod for s in slices)
