"""Load catalog assets into a PyBullet client: URDF, link lookup, colour randomisation, state visuals."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.errors import AssetError
from luminous_sim.world.client import BulletClient, p


@dataclass
class LoadedAsset:
    """A catalog asset living in one client."""

    entry: AssetEntry
    body: int
    link_index: dict[str, int]
    joint_index: dict[str, int]
    colors: dict[tuple[str, int], list[float]] = field(default_factory=dict)
    """Current colour of each (link, visual index), alpha excluded from state toggling."""
    alphas: dict[tuple[str, int], float] = field(default_factory=dict)
    """Current alpha of each (link, visual index): 0 for a hidden state visual."""
    last_set: dict[str, int] = field(default_factory=dict)
    """The visual of each link whose colour was set last: `getVisualShapeData` reports that colour for
    every visual of the link (what is drawn keeps each visual's own)."""
    lod: bool = False
    """Whether the level-of-detail visuals were loaded (what replaces this body, its slices, loads the same)."""


def main_slot(entry: AssetEntry) -> str:
    """The material slot of the base link's first visual: what a CDF colour applies to."""
    return next(v["slot"] for v in entry.visuals if v["state"] is None)


def load_asset(
    client: BulletClient, entry: AssetEntry, position=(0.0, 0.0, 0.0), yaw: float = 0.0,
    fixed: bool = False, rng: np.random.Generator | None = None, color: tuple[float, float, float] | None = None,
    lod: bool = False,
) -> LoadedAsset:
    """Load `entry` (at its `scale`) at `position` turned by `yaw` (radians about z); with `rng`,
    randomise its colours; `color` overrides its main material slot; `lod` loads its level-of-detail
    visuals (same links, joints, collision and visual order)."""
    urdf = entry.urdf_for(lod)
    if not urdf.is_file():
        raise AssetError(f"asset {entry.id}: {urdf} is missing; rebuild it with "
                         f"`luminous assets build --types {entry.type}`")
    orn = client.getQuaternionFromEuler([0, 0, yaw])
    body = client.loadURDF(
        str(urdf), list(position), orn, useFixedBase=fixed,
        flags=p.URDF_USE_INERTIA_FROM_FILE | p.URDF_MAINTAIN_LINK_ORDER, globalScaling=entry.scale,
    )
    link_index = {"base": -1}
    joint_index = {}
    for j in range(client.getNumJoints(body)):
        info = client.getJointInfo(body, j)
        link_index[info[12].decode()] = j
        joint_index[info[1].decode()] = j
    loaded = LoadedAsset(entry, body, link_index, joint_index, lod=lod and bool(entry.lod_urdf))
    palettes = entry.palettes
    for vis in entry.visuals:
        choices = palettes[vis["slot"]]
        idx = entry.variant % len(choices) if rng is None else int(rng.integers(len(choices)))
        loaded.colors[(vis["link"], vis["index"])] = list(choices[idx])
    for vis in entry.visuals:
        key = (vis["link"], vis["index"])
        loaded.alphas[key] = 0.0 if vis["state"] in HIDDEN_STATES else loaded.colors[key][3]
    if color is not None:
        slot = main_slot(entry)
        for vis in entry.visuals:
            if vis["slot"] == slot:
                loaded.colors[(vis["link"], vis["index"])] = [*color, 1.0]
    if rng is not None or color is not None:
        for vis in entry.visuals:
            set_visual_alpha(client, loaded, vis["link"], vis["index"], default_alpha(vis["state"]))
    return loaded


HIDDEN_STATES = ("on", "dirty", "open")
"""State visuals hidden when an asset is loaded (the URDF gives them alpha 0)."""


def default_alpha(state: str | None) -> float:
    return 0.0 if state in HIDDEN_STATES else 1.0


_visual_changes = [0]


def visual_changes() -> int:
    """How many times `set_visual_alpha` has changed a visual in this process (readers of `LoadedAsset` colours
    compare it to know whether to read them again)."""
    return _visual_changes[0]


def set_visual_alpha(client: BulletClient, loaded: LoadedAsset, link: str, index: int, alpha: float) -> None:
    """Show (alpha 1) or hide (alpha 0: gone from RGB and segmentation) one visual of an asset."""
    _visual_changes[0] += 1
    rgba = list(loaded.colors[(link, index)][:3]) + [alpha]
    loaded.alphas[(link, index)] = alpha
    loaded.last_set[link] = index
    client.changeVisualShape(loaded.body, loaded.link_index[link], shapeIndex=index, rgbaColor=rgba)


def show_state(client: BulletClient, loaded: LoadedAsset, state: str, active: bool) -> None:
    """Make the visuals tagged `state` visible iff `active` (and their opposite visible iff not)."""
    opposite = {"on": "off", "off": "on", "dirty": "clean", "clean": "dirty", "open": "closed",
                "closed": "open"}[state]
    for vis in loaded.entry.visuals:
        if vis["state"] == state:
            set_visual_alpha(client, loaded, vis["link"], vis["index"], 1.0 if active else 0.0)
        elif vis["state"] == opposite:
            set_visual_alpha(client, loaded, vis["link"], vis["index"], 0.0 if active else 1.0)


def set_joint(client: BulletClient, loaded: LoadedAsset, joint: str, value: float) -> None:
    """Put a joint at `value` (rad or m) and hold it there with its motor."""
    j = loaded.joint_index[joint]
    client.resetJointState(loaded.body, j, value)
    client.setJointMotorControl2(loaded.body, j, p.POSITION_CONTROL, targetPosition=value, force=200)


def base_link_pose(client: BulletClient, body: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The pose of the base *link* frame (PyBullet reports the base's inertial frame instead)."""
    pos, orn = client.getBasePositionAndOrientation(body)
    local_pos, local_orn = client.getDynamicsInfo(body, -1)[3:5]
    inv_pos, inv_orn = client.invertTransform(local_pos, local_orn)
    return client.multiplyTransforms(pos, orn, inv_pos, inv_orn)
