"""A scene under construction: objects placed so far, their footprints and ids."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from shapely.geometry import Polygon
from shapely.ops import unary_union

from luminous_sim.assets.catalog import AssetEntry, Catalog
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Layer, Scene, SceneObject, blocks_agent, footprint, reachable_grid
from luminous_sim.scene.ids import thor_object_id

SEGMENTED_FIXTURES = {"CounterTop"}
"""Fixture types built from several segments that a CDF names as one object."""


@dataclass
class Placed:
    obj: SceneObject
    entry: AssetEntry
    footprint: Polygon


@dataclass
class SceneDraft:
    """Objects placed so far. Every random draw comes from `rng`."""

    shell: RoomShell
    catalog: Catalog
    rng: np.random.Generator
    placed: list[Placed] = field(default_factory=list)
    taken_ids: set[str] = field(default_factory=set)
    memo: dict = field(default_factory=dict)
    """Values derived from placed objects (receptacle regions), keyed by what they depend on."""

    def add(
        self, entry: AssetEntry, x: float, y: float, z: float, yaw: float, layer: Layer, fixed: bool,
        parent: str | None = None, region: str | None = None, name: str | None = None,
        states: dict[str, bool] | None = None, color: tuple[float, float, float] | None = None,
    ) -> SceneObject:
        obj = SceneObject(
            id=thor_object_id(entry.type, (x, y, z), self.taken_ids), type=entry.type, asset=entry.id,
            position=(x, y, z), yaw=yaw, layer=layer, fixed=fixed, parent=parent, region=region, name=name,
            states=states or {}, color_seed=int(self.rng.integers(2**31)), scale=entry.scale, color=color,
        )
        self.placed.append(Placed(obj, entry, footprint(entry, obj.position[0], obj.position[1], obj.yaw)))
        return obj

    def referents(self, obj_id: str | None) -> list[Placed]:
        """What a CDF name bound to `obj_id` refers to: that object, or every segment of its fixture
        run (the kitchen's counter), so "a coffee machine on the counter" may go on any segment."""
        hit = next((p for p in self.placed if p.obj.id == obj_id), None)
        if hit is None or hit.obj.type not in SEGMENTED_FIXTURES or hit.obj.layer != "fixture":
            return [hit] if hit is not None else []
        return [p for p in self.placed if p.obj.type == hit.obj.type and p.obj.layer == "fixture"]

    def floor_obstacles(self) -> Polygon:
        """Union of the footprints of everything standing on the floor."""
        return unary_union([p.footprint for p in self.placed if p.obj.parent is None and p.obj.layer != "structure"])

    def reachable_grid(self) -> np.ndarray:
        """The agent's reachable 0.25 m grid among the things placed so far (`scene.reachable_grid`)."""
        return reachable_grid(self.shell, [p.footprint for p in self.placed if blocks_agent(p.obj, p.entry)])

    def pick_variant(self, object_type: str, fits=lambda e: True) -> AssetEntry | None:
        """A uniformly drawn variant of a type that satisfies `fits`, or None."""
        options = [e for e in self.catalog.of_type(object_type) if fits(e)]
        if not options:
            return None
        return options[int(self.rng.integers(len(options)))]

    def to_scene(self, generator: str, seed: int, source: str = "", notes: dict | None = None) -> Scene:
        return Scene(room=self.shell, seed=seed, generator=generator,
                     objects=tuple(p.obj for p in self.placed), source=source, notes=notes or {})
