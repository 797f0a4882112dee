"""The room-structure layer: kitchen and bathroom fixtures from the shell's fixture plan.

Counter runs are tiled with CounterTop segments; the sink slot gets a Sink with its SinkBasin and
Faucet (the Sink's anchors), the stove slot four StoveBurners on the counter and StoveKnobs on its
front, the fridge slot a Fridge; bathrooms get their Toilet, Sink and Bathtub (with its basin) or shower
stall (ShowerHead, ShowerDoor, ShowerGlass), and a counter beside the sink where the vanity is long
enough. A sink or cooktop counter wider than its slot keeps within what is left of its run, so that it
does not run into the next fixture.
"""

from __future__ import annotations

import math

import numpy as np

from luminous_sim.assets.catalog import AssetEntry, Catalog
from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.rooms.shell import CounterRun, FixtureSlot, RoomShell, Wall
from luminous_sim.scene import Scene, SceneObject, against_wall, footprint, local_to_world

GAP = 0.01
CLEAR_STEP = 0.05
"""How far (m) a counter segment that would run into a fixture already there moves along its wall."""
OVERLAP_AREA = 1e-4
"""Footprint overlap (m^2) that counts as running into another fixture (the validation report's figure)."""


def _width(e: AssetEntry) -> float:
    return e.dims[0]


def _clamped(wall: Wall, entry: AssetEntry, u_start: float) -> float:
    """The start along the wall that keeps the asset within it, clear of the walls at both ends (a slot at a
    corner, a wider asset)."""
    return min(max(u_start, GAP), wall.length - _width(entry) - GAP)


def _footprint_against(wall: Wall, entry: AssetEntry, u_start: float):
    """The footprint of the asset with its back against `wall` from `u_start` (as `_add_against` puts it)."""
    pose = against_wall(wall, entry, _clamped(wall, entry, u_start), GAP)
    return footprint(entry, pose.x, pose.y, pose.yaw)


def _runs_into(fp, others) -> bool:
    """Whether footprint `fp` overlaps any of the polygons `others` by more than OVERLAP_AREA."""
    return any(fp.intersects(o) and fp.intersection(o).area > OVERLAP_AREA for o in others)


def _free(draft: SceneDraft, fp, keep_clear=()) -> bool:
    """Whether a fixture footprint stays on the floor (a converted room's wall may jut out within a
    fixture's depth) and clear of the free-standing fixtures placed so far and of `keep_clear`."""
    return draft.shell.polygon().buffer(0.005).contains(fp) and not _runs_into(
        fp, [p.footprint for p in draft.placed if p.obj.parent is None] + list(keep_clear))


def _clear(draft: SceneDraft, wall: Wall, entry: AssetEntry, u_start: float) -> bool:
    """Whether a counter segment against `wall` from `u_start` keeps clear of every fixture placed so far (a
    room converted from AI2-THOR may have a run that stops short of a corner, or a fridge, within our deeper
    counters' reach)."""
    fp = _footprint_against(wall, entry, u_start)
    return not _runs_into(fp, [p.footprint for p in draft.placed if p.obj.parent is None])


MAX_SHIFT = 0.5
"""How far (m) a free-standing fixture may move along its wall from its slot to keep clear of others."""


def _nearest_free(draft: SceneDraft, wall: Wall, entry: AssetEntry, u_start: float) -> float | None:
    """`u_start` if the asset is `_free` there, else the nearest start within MAX_SHIFT along the wall where it
    is `_free` and off every door's clearance zone; None if there is none."""
    if _free(draft, _footprint_against(wall, entry, u_start)):
        return u_start
    doors = draft.shell.door_clearance_zones()
    steps = round(MAX_SHIFT / CLEAR_STEP)
    for k in sorted(range(-steps, steps + 1), key=lambda k: (abs(k), k)):
        u = u_start + k * CLEAR_STEP
        if GAP <= u <= wall.length - _width(entry) - GAP and _free(draft, _footprint_against(wall, entry, u), doors):
            return u
    return None


def _add_against(draft: SceneDraft, wall: Wall, entry: AssetEntry, u_start: float, z: float = 0.0,
                 v_extra: float = 0.0, fixed: bool = True) -> SceneObject:
    u_start = _clamped(wall, entry, u_start)
    pose = against_wall(wall, entry, u_start, GAP, v_extra)
    return draft.add(entry, pose.x, pose.y, z - entry.bbox_min[2], pose.yaw, "fixture", fixed)


def add_anchors(draft: SceneDraft, host: SceneObject, entry: AssetEntry) -> list[SceneObject]:
    """The objects an asset brings along (a Sink's SinkBasin and Faucet), at their anchor poses."""
    out = []
    for anchor in entry.anchors:
        variants = draft.catalog.of_type(anchor["type"])
        if not variants:
            continue
        sub = variants[entry.variant % len(variants)]
        ax, ay, az, ayaw = anchor["pose"]
        x, y = local_to_world(host.position[0], host.position[1], host.yaw, (ax, ay))
        out.append(draft.add(sub, x, y, host.position[2] + az, host.yaw + ayaw, "fixture", True,
                             parent=host.id))
    return out


def _tile_counter(draft: SceneDraft, wall: Wall, a: float, b: float) -> list[SceneObject]:
    """Fill [a, b] along a wall with straight CounterTop segments, widest first."""
    straight = [e for e in draft.catalog.of_type("CounterTop") if e.dims[1] < 0.9]
    out, u, b = [], max(a, GAP), min(b, wall.length - GAP)  # clear of the walls at both ends
    while straight:
        fits = [e for e in straight if _width(e) <= b - u + 1e-6]
        if not fits:
            break
        fits = [e for e in fits if _clear(draft, wall, e, u)]
        if not fits:
            u += CLEAR_STEP
            continue
        widest = max(_width(e) for e in fits)
        choice = [e for e in fits if abs(_width(e) - widest) < 1e-6]
        entry = choice[int(draft.rng.integers(len(choice)))]
        out.append(_add_against(draft, wall, entry, u))
        u += _width(entry)
    return out


def _room_tag(draft: SceneDraft) -> str:
    return {"LivingRoom": "living_room"}.get(draft.shell.room_type, draft.shell.room_type.lower())


def _pick_sink(draft: SceneDraft, width: float) -> AssetEntry | None:
    """A sink of this room's kind (kitchen unit or bathroom vanity) that fits the slot, else the narrowest."""
    tag = _room_tag(draft)
    ours = [e for e in draft.catalog.of_type("Sink") if tag in e.tags] or draft.catalog.of_type("Sink")
    fitting = [e for e in ours if _width(e) <= width + 1e-6]
    if fitting:
        return fitting[int(draft.rng.integers(len(fitting)))]
    return min(ours, key=_width, default=None)


def _stove_counter(draft: SceneDraft, slot: FixtureSlot) -> AssetEntry | None:
    """The counter segment the burners stand on: the narrowest one at least as wide as the cooktop."""
    straight = [e for e in draft.catalog.of_type("CounterTop") if e.dims[1] < 0.9]
    wide = [e for e in straight if _width(e) >= slot.width - 1e-6]
    if not wide:
        return None
    narrowest = min(_width(e) for e in wide)
    choice = [e for e in wide if abs(_width(e) - narrowest) < 1e-6]
    return choice[int(draft.rng.integers(len(choice)))]


def _stove(draft: SceneDraft, wall: Wall, slot: FixtureSlot, counter_top: float, depth: float,
           host: str | None) -> None:
    burner = draft.pick_variant("StoveBurner")
    knob = draft.pick_variant("StoveKnob")
    if burner is None:
        return
    yaw = math.atan2(-wall.normal[0], wall.normal[1])
    width = max(slot.width, 0.6)
    mid = slot.offset + width / 2
    bw, bd = burner.dims[0] + 0.02, burner.dims[1] + 0.02
    cols = max(1, min(2, int(width // bw)))
    rows = max(1, min(2, int((depth - 0.04) // bd)))
    for i in range(cols):
        du = (i - (cols - 1) / 2) * bw
        for j in range(rows):
            dv = 0.03 + bd / 2 + j * bd
            x, y = wall.point(mid + du - (burner.bbox_min[0] + burner.bbox_max[0]) / 2,
                              GAP + dv - (burner.bbox_min[1] + burner.bbox_max[1]) / 2)
            draft.add(burner, x, y, counter_top - burner.bbox_min[2], yaw, "fixture", True, parent=host)
        if knob is not None:
            for k in (-0.05, 0.05):
                kx, ky = wall.point(mid + du + k, GAP + depth - knob.bbox_min[1])
                draft.add(knob, kx, ky, counter_top - 0.12, yaw, "fixture", True, parent=host)


def _within(slot: FixtureSlot, width: float, lo: float, hi: float) -> float:
    """Where a piece `width` wide starts in its slot: centred (at the slot's start when wider), then moved
    as little as needed to stay within [lo, hi] (what is left of its counter run) where it fits there."""
    start = slot.offset + max(0.0, (slot.width - width) / 2)
    return min(max(start, lo), hi - width) if hi - lo >= width - 1e-9 else start


def _meets_run(shell: RoomShell, run: CounterRun, at_start: bool) -> bool:
    """Whether the run's start (end) meets another counter run that turns the corner there."""
    walls = list(shell.walls)
    i = next(k for k, w in enumerate(walls) if w.id == run.wall)
    wall = walls[i]
    if (run.start <= 1e-6) if at_start else (run.end >= wall.length - 1e-6):
        return False
    other = walls[(i - 1) % len(walls)] if at_start else walls[(i + 1) % len(walls)]
    return any(r.wall == other.id and ((r.end >= other.length - 1e-6) if at_start else (r.start <= 1e-6))
               for r in shell.fixtures.counters if r is not run)


def _fill_run(draft: SceneDraft, wall: Wall, run: CounterRun, slots: list[FixtureSlot], depth: float) -> None:
    """Tile one counter run with CounterTop segments around its sink and cooktop slots."""
    # where a run meets another run's corner square, our counters may be a little deeper than the
    # plan's depth: keep that much clear
    extra = max(0.0, depth - run.depth) + GAP + 0.01
    u = run.start + (extra if _meets_run(draft.shell, run, at_start=True) else 0.0)
    end = run.end - (extra if _meets_run(draft.shell, run, at_start=False) else 0.0)
    for slot, nxt in zip(slots, [*slots[1:], None]):
        if slot.type not in ("Sink", "StoveBurner"):
            continue
        hi = end if nxt is None else nxt.offset  # the next slot's piece starts there
        entry = _pick_sink(draft, slot.width) if slot.type == "Sink" else _stove_counter(draft, slot)
        start = slot.offset if entry is None else _clamped(wall, entry, _within(slot, _width(entry), u, hi))
        _tile_counter(draft, wall, u, start)
        u = slot.offset + slot.width
        if entry is None:
            continue
        host = _add_against(draft, wall, entry, start)
        if slot.type == "Sink":
            add_anchors(draft, host, entry)
        else:
            _stove(draft, wall, slot, host.position[2] + entry.bbox_max[2], run.depth, host.id)
        u = max(u, start + _width(entry))  # a piece wider than its slot pushes the next counter along
    _tile_counter(draft, wall, u, end)


SHOWER_HEAD_TOP = 2.0
"""Height (m) of the top of a shower head's wall fitting."""
FLAT_PANEL = 0.2
"""Depth (m) under which a glass screen is one flat panel (not L-shaped)."""


def _shower(draft: SceneDraft, wall: Wall, slot: FixtureSlot) -> None:
    """A shower stall in its slot: a head on the back wall, a door across the front, and a glass side
    panel on each side not against a wall (just outside the slot, where that floor is free)."""
    door = draft.pick_variant("ShowerDoor", lambda e: _width(e) <= slot.width + 1e-6)
    head = draft.pick_variant("ShowerHead")
    glass = draft.pick_variant("ShowerGlass", lambda e: e.dims[1] < FLAT_PANEL and e.dims[2] > SHOWER_HEAD_TOP - 0.2
                               and _width(e) <= slot.depth + 1e-6)
    mid = slot.offset + slot.width / 2
    if head is not None:
        _add_against(draft, wall, head, mid - _width(head) / 2, z=SHOWER_HEAD_TOP - head.dims[2])
    if door is not None:
        _add_against(draft, wall, door, mid - _width(door) / 2, v_extra=slot.depth - door.dims[1] - GAP)
    if glass is None:
        return
    yaw = wall.yaw + math.pi / 2  # the panel's width runs from the wall into the room
    centre = local_to_world(0.0, 0.0, yaw, ((glass.bbox_min[0] + glass.bbox_max[0]) / 2,
                                            (glass.bbox_min[1] + glass.bbox_max[1]) / 2))
    half_t = glass.dims[1] / 2
    for u in (slot.offset - half_t, slot.offset + slot.width + half_t):
        x, y = wall.point(u, GAP + _width(glass) / 2)
        x, y = x - centre[0], y - centre[1]
        if _free(draft, footprint(glass, x, y, yaw)):  # a side against a wall needs no glass
            draft.add(glass, x, y, -glass.bbox_min[2], yaw, "fixture", True)


def place_fixtures(draft: SceneDraft) -> None:
    """Add every fixture of the shell's fixture plan to the draft."""
    shell = draft.shell
    walls = {w.id: w for w in shell.walls}
    slots_in: dict[str, list[FixtureSlot]] = {}
    for slot in shell.fixtures.slots:
        if slot.counter:
            slots_in.setdefault(slot.counter, []).append(slot)
    depth = max((e.dims[1] for e in draft.catalog.of_type("CounterTop") if e.dims[1] < 0.9), default=0.6)
    for run in shell.fixtures.counters:
        _fill_run(draft, walls[run.wall], run, sorted(slots_in.get(run.id, []), key=lambda s: s.offset), depth)
    for slot in shell.fixtures.slots:
        if slot.counter:
            continue
        wall = walls[slot.wall]
        if slot.type == "Shower":
            _shower(draft, wall, slot)
            continue

        def start(e: AssetEntry, s: FixtureSlot = slot) -> float:
            return s.offset + max(0.0, (s.width - _width(e)) / 2)

        # each variant's start: its slot, else nearby along the wall (None: nowhere)
        places = {e.id: _nearest_free(draft, wall, e, start(e))
                  for e in draft.catalog.of_type(slot.type) if _width(e) <= slot.width + 0.05}
        # a variant that fits its slot as planned, else one that must move to keep clear
        entry = draft.pick_variant(slot.type, lambda e, p=places: p.get(e.id) == start(e)) or \
            draft.pick_variant(slot.type, lambda e, p=places: p.get(e.id) is not None)
        if entry is None:
            continue
        u = places[entry.id]
        host = _add_against(draft, wall, entry, u)
        add_anchors(draft, host, entry)


def fixture_types(shell: RoomShell, catalog: Catalog) -> set[str]:
    """The types of the fixtures `place_fixtures` puts in this shell (independent of the draws)."""
    draft = SceneDraft(shell, catalog, np.random.default_rng(0))
    place_fixtures(draft)
    return {p.obj.type for p in draft.placed}


def structure_scene(shell: RoomShell, seed: int, catalog: Catalog) -> Scene:
    """The room's fixtures alone, as `generate`'s first attempt lays them (its structure layer, same draws):
    what a generator that furnishes only the rest of the room (a learned one) is given with the room."""
    draft = SceneDraft(shell, catalog, np.random.default_rng(np.random.SeedSequence([seed, 0])))
    place_fixtures(draft)
    return draft.to_scene("structure", seed)
