"""Slicing: the object's body is replaced by its slices, laid out as its catalog SliceSpec says."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.assets.catalog import scaled
from luminous_sim.world.asset_loader import base_link_pose, load_asset

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def slice_body(world: World, oid: str, sliced_type: str | None) -> None:
    """Replace the object by its slices (ids `<oid>|<SlicedType>_<n>`), laid out as its SliceSpec says."""
    loaded = world.built.objects[oid]
    spec = loaded.entry.slices
    if not spec or sliced_type is None:
        return
    variants = world.catalog.of_type(spec["type"])
    if not variants:
        return
    slice_entry = scaled(next((e for e in variants if e.variant == loaded.entry.variant), variants[0]),
                         loaded.entry.scale)
    c = world.client
    pos, orn = base_link_pose(c, loaded.body)
    c.removeBody(loaded.body)
    del world.built.objects[oid]
    for i, (sx, sy, sz, syaw) in enumerate(spec["poses"]):
        wpos, _ = c.multiplyTransforms(pos, orn, [sx, sy, sz + 0.002], [0, 0, 0, 1])
        yaw = c.getEulerFromQuaternion(orn)[2] + syaw
        new = load_asset(c, slice_entry, wpos, yaw, rng=np.random.default_rng(i), lod=loaded.lod)
        world.built.objects[f"{oid}|{sliced_type}_{i + 1}"] = new
