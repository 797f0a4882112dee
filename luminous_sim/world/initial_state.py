"""The pure object state (`luminous_sim.states`) of a freshly built scene: the CDF's initial states,
which knob works which burner, which faucet fills which basin, and how many slices each sliceable makes."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.states.model import ObjectState, Temperature, WorldState
from luminous_sim.vocab import BASINS

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def initial_state(world: World) -> WorldState:
    """The pure state of a freshly built scene."""
    objs = {}
    for o in world.scene.objects:
        objs[o.id] = ObjectState(
            o.id, o.type, isOpen=bool(o.states.get("isOpen", False)), isToggled=bool(o.states.get("isToggled", False)),
            isDirty=bool(o.states.get("isDirty", False)), parent=o.parent, temperature=_temperature(o.states),
            isFilledWithLiquid=bool(o.states.get("isFilled", False)),
        )
    slices = {oid: loaded.entry.slices["count"] for oid, loaded in world.built.objects.items() if loaded.entry.slices}
    return WorldState(objs, held=None, heated=frozenset(), cooled=frozenset(), cleaned=frozenset(),
                      controls=_controls(world), faucet_basin=_faucet_basins(world), slice_counts=slices)


def _temperature(states: Mapping[str, object]) -> Temperature:
    """A CDF's initial isHot/isCold as a temperature (physical only: ALFRED's isHot means "was heated")."""
    return "Hot" if states.get("isHot") else "Cold" if states.get("isCold") else "RoomTemp"


def _nearest(world: World, oid: str, candidates: list[str]) -> str | None:
    if not candidates:
        return None
    here = np.array(world.scene.object(oid).position)
    return min(candidates, key=lambda c: (float(np.linalg.norm(np.array(world.scene.object(c).position) - here)), c))


def _faucet_basins(world: World) -> dict[str, str]:
    basins = [o.id for o in world.scene.objects if o.type in BASINS]
    return {o.id: b for o in world.scene.objects if o.type == "Faucet" for b in [_nearest(world, o.id, basins)] if b}


def _controls(world: World) -> dict[str, str]:
    burners = [o.id for o in world.scene.objects if o.type == "StoveBurner"]
    out: dict[str, str] = {}
    for o in world.scene.objects:
        if o.type == "StoveKnob":
            free = [b for b in burners if b not in out.values()] or burners
            b = _nearest(world, o.id, free)
            if b:
                out[o.id] = b
    return out
