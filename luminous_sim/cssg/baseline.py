"""The uniform-random baseline: fixtures as planned, then furniture, wall pieces and objects at uniformly
random free positions and headings, with no relations. CSSG is compared against it."""

from __future__ import annotations

import math

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.pose import footprint
from luminous_sim.cssg.regions import RegionSpot, fits, region_spots, sample_in_region
from luminous_sim.cssg.structure import place_fixtures
from luminous_sim.cssg.tables import layer_of, room_defaults, supports_for
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene.model import Scene
from luminous_sim.vocab import room_objects

FURNITURE_TRIES = 200


def _furniture_counts(room_type: str, rng: np.random.Generator) -> list[str]:
    out = []
    for t, (lo, hi) in sorted(room_defaults(room_type)["furniture"].items()):
        out += [t] * int(rng.integers(lo, hi + 1))
    return out


def _object_types(room_type: str, rng: np.random.Generator) -> list[str]:
    """Small objects drawn with ALFRED's per-room frequencies (how many of its 30 scenes hold each)."""
    out = []
    for t, n in sorted(room_objects(room_type).items()):
        if layer_of(t) == "object" and supports_for(t) and rng.random() < n / 30:
            out.append(t)
    return out


def place_furniture_uniform(draft: SceneDraft, types: list[str]) -> list[str]:
    """Uniformly random position and heading for each type; returns the types that did not fit."""
    floor = draft.shell.polygon()
    keep_clear = draft.shell.door_clearance_zones()
    minx, miny, maxx, maxy = floor.bounds
    failed = []
    for t in types:
        for _ in range(FURNITURE_TRIES):
            entry = draft.pick_variant(t)
            if entry is None:
                break
            x, y = draft.rng.uniform(minx, maxx), draft.rng.uniform(miny, maxy)
            yaw = float(draft.rng.uniform(0, 2 * math.pi))
            fp = footprint(entry, x, y, yaw)
            if not floor.contains(fp) or any(fp.intersects(z) for z in keep_clear):
                continue
            if fp.intersects(draft.floor_obstacles()):
                continue
            draft.add(entry, x, y, -entry.bbox_min[2], yaw, "furniture", fixed=True)
            break
        else:
            failed.append(t)
    return failed


def place_objects(draft: SceneDraft, types: list[str], uniform: bool = True) -> list[str]:
    """Put each object type on a random compatible region of a placed receptacle; returns failures."""
    occupied: dict[tuple[str, str], list[Polygon]] = {}
    failed = []
    for t in types:
        allowed = supports_for(t)
        spots: list[RegionSpot] = [
            s for p in list(draft.placed) if p.obj.type in allowed for s in region_spots(p.obj, p.entry)
        ]
        entry = draft.pick_variant(t)
        candidates = [s for s in spots if entry is not None and fits(entry, s)]
        if not candidates:
            failed.append(t)
            continue
        for attempt in range(10):
            spot = candidates[int(draft.rng.integers(len(candidates)))]
            key = (spot.host.id, spot.name)
            got = sample_in_region(entry, spot, draft.rng, occupied.get(key, []), yaw_choices=4)
            if got is None:
                continue
            x, y, z, yaw, fp = got
            occupied.setdefault(key, []).append(fp)
            draft.add(entry, x, y, z, yaw, "object", fixed=False, parent=spot.host.id, region=spot.name)
            break
        else:
            failed.append(t)
    return failed


def generate_uniform(shell: RoomShell, seed: int, catalog: Catalog | None = None) -> Scene:
    """A scene with the room's default furniture and ALFRED-frequency objects, placed uniformly at random."""
    rng = np.random.default_rng(np.random.SeedSequence(seed))
    draft = SceneDraft(shell, catalog or default_catalog(), rng)
    place_fixtures(draft)
    failed = place_furniture_uniform(draft, _furniture_counts(shell.room_type, rng))
    failed += place_objects(draft, _object_types(shell.room_type, rng))
    return draft.to_scene("uniform", seed, notes={"unplaced": failed})
