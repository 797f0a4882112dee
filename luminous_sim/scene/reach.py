"""How far from a thing the agent may stand and still reach it, measured from the eye as ALFRED does."""

from __future__ import annotations

import math

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT, VISIBILITY_DISTANCE

REACH = VISIBILITY_DISTANCE - 0.05
"""Every piece must stay within this distance of the eye over walkable floor (ALFRED reaches 1.5 m)."""


def horizontal_reach(bottom: float, top: float, reach: float = REACH) -> float:
    """How far (m, on the floor) the agent may stand from a thing spanning heights `bottom`..`top` and still
    have its eye within `reach` of it, as ALFRED measures reach: a garbage can must be much nearer than a
    fridge."""
    gap = max(0.0, CAMERA_HEIGHT - top, bottom - CAMERA_HEIGHT)
    return math.sqrt(max(reach * reach - gap * gap, 0.0))


def reach_of(entry: AssetEntry, z: float, reach: float = REACH) -> float:
    """`horizontal_reach` of an asset standing with its origin at height `z`."""
    return horizontal_reach(z + entry.bbox_min[2], z + entry.bbox_max[2], reach)
