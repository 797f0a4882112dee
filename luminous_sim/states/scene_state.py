"""The pure object state of a scene as built, without physics: the CDF's initial states, which knob works
which burner, which faucet fills which basin (the nearest of each), and how many slices each sliceable makes
(its asset's count). The one copy: a `World` starts from it, and so does the text game."""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.states.model import ObjectState, Temperature, WorldState
from luminous_sim.vocab import BASINS

if TYPE_CHECKING:
    from luminous_sim.assets.catalog import Catalog
    from luminous_sim.scene import Scene


def scene_state(scene: Scene, catalog: Catalog | None = None) -> WorldState:
    """The state of a freshly built scene (`catalog`: the asset library it is built from, the default one
    if None)."""
    from luminous_sim.assets.catalog import default_catalog

    catalog = catalog or default_catalog()
    objs = {}
    slices = {}
    for o in scene.objects:
        objs[o.id] = ObjectState(
            o.id, o.type, isOpen=bool(o.states.get("isOpen", False)), isToggled=bool(o.states.get("isToggled", False)),
            isDirty=bool(o.states.get("isDirty", False)), parent=o.parent, temperature=_temperature(o.states),
            isFilledWithLiquid=bool(o.states.get("isFilled", False)),
        )
        entry = catalog.for_object(o)
        if entry.slices:
            slices[o.id] = entry.slices["count"]
    return WorldState(objs, held=None, heated=frozenset(), cooled=frozenset(), cleaned=frozenset(),
                      controls=_controls(scene), faucet_basin=_faucet_basins(scene), slice_counts=slices)


def _temperature(states: Mapping[str, object]) -> Temperature:
    """A CDF's initial isHot/isCold as a temperature (physical only: ALFRED's isHot means "was heated")."""
    return "Hot" if states.get("isHot") else "Cold" if states.get("isCold") else "RoomTemp"


def _nearest(scene: Scene, oid: str, candidates: list[str]) -> str | None:
    if not candidates:
        return None
    here = np.array(scene.object(oid).position)
    return min(candidates, key=lambda c: (float(np.linalg.norm(np.array(scene.object(c).position) - here)), c))


def _faucet_basins(scene: Scene) -> dict[str, str]:
    basins = [o.id for o in scene.objects if o.type in BASINS]
    return {o.id: b for o in scene.objects if o.type == "Faucet" for b in [_nearest(scene, o.id, basins)] if b}


def _controls(scene: Scene) -> dict[str, str]:
    burners = [o.id for o in scene.objects if o.type == "StoveBurner"]
    out: dict[str, str] = {}
    for o in scene.objects:
        if o.type == "StoveKnob":
            free = [b for b in burners if b not in out.values()] or burners
            b = _nearest(scene, o.id, free)
            if b:
                out[o.id] = b
    return out
