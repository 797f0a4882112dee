"""Opening and closing: a door, drawer or lid's joint goes to its open or closed limit, and what lies
in a drawer slides out and back with it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.states.model import WorldState
from luminous_sim.world.asset_loader import set_joint
from luminous_sim.world.hand import move_rigidly

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def move_joint(world: World, state: WorldState, oid: str, open_: bool) -> None:
    """Open or close every door, drawer and lid of the object."""
    loaded = world.built.objects[oid]
    c = world.client
    for j in loaded.entry.joints:
        if j["role"] not in ("door", "drawer", "lid"):
            continue
        link = loaded.link_index[j["child"]]
        before = c.getLinkState(loaded.body, link, computeForwardKinematics=True)[4:6]
        set_joint(c, loaded, j["name"], j["upper"] if open_ else j["lower"])
        after = c.getLinkState(loaded.body, link, computeForwardKinematics=True)[4:6]
        if j["role"] == "drawer":  # what lies in a drawer slides out with it
            inside = [o for o in state.contents(oid, recursive=True) if _in_link(world, o, oid, j["child"])]
            move_rigidly(world, inside, before, after)


def _in_link(world: World, oid: str, host: str, link: str) -> bool:
    """Whether an object sits in a region that belongs to `link` of `host` (a drawer's inside)."""
    scene_ids = {o.id: o for o in world.scene.objects}
    region = scene_ids[oid].region if oid in scene_ids else None
    entry = world.built.objects[host].entry
    return any(r["name"] == region and r["link"] == link for r in entry.regions)
