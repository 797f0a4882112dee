"""The room-structure layer: kitchen and bathroom fixtures from the shell's fixture plan.

Counter runs are tiled with CounterTop segments; the sink slot gets a Sink with its SinkBasin and
Faucet (the Sink's anchors), the stove slot four StoveBurners on the counter and StoveKnobs on its
front, the fridge slot a Fridge; bathrooms get their Toilet, Sink and Bathtub (with its basin).
"""

from __future__ import annotations

import math

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.pose import against_wall, local_to_world
from luminous_sim.rooms.shell import CounterRun, FixtureSlot, Wall
from luminous_sim.scene.model import SceneObject

GAP = 0.01


def _width(e: AssetEntry) -> float:
    return e.dims[0]


def _add_against(draft: SceneDraft, wall: Wall, entry: AssetEntry, u_start: float, z: float = 0.0,
                 v_extra: float = 0.0, fixed: bool = True) -> SceneObject:
    # stay within the wall, clear of the walls at both ends (a slot at a corner, a wider asset)
    u_start = min(max(u_start, GAP), wall.length - _width(entry) - GAP)
    pose = against_wall(wall, entry, u_start, GAP, v_extra)
    return draft.add(entry, pose.x, pose.y, z - entry.bbox_min[2], pose.yaw, "fixture", fixed)


def _add_anchors(draft: SceneDraft, host: SceneObject, entry: AssetEntry) -> list[SceneObject]:
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
    out, u = [], a
    while straight:
        fits = [e for e in straight if _width(e) <= b - u + 1e-6]
        if not fits:
            break
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


def _stove_counter(draft: SceneDraft, wall: Wall, slot: FixtureSlot) -> SceneObject | None:
    """The counter segment the burners stand on: the narrowest one at least as wide as the cooktop."""
    straight = [e for e in draft.catalog.of_type("CounterTop") if e.dims[1] < 0.9]
    wide = [e for e in straight if _width(e) >= slot.width - 1e-6]
    if not wide:
        return None
    narrowest = min(_width(e) for e in wide)
    choice = [e for e in wide if abs(_width(e) - narrowest) < 1e-6]
    return _add_against(draft, wall, choice[int(draft.rng.integers(len(choice)))], slot.offset)


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


def _counter_top_height(draft: SceneDraft) -> float:
    tops = [e.bbox_max[2] for e in draft.catalog.of_type("CounterTop")]
    return max(tops) if tops else 0.9


def place_fixtures(draft: SceneDraft) -> None:
    """Add every fixture of the shell's fixture plan to the draft."""
    shell = draft.shell
    walls = {w.id: w for w in shell.walls}
    slots_in: dict[str, list[FixtureSlot]] = {}
    for slot in shell.fixtures.slots:
        if slot.counter:
            slots_in.setdefault(slot.counter, []).append(slot)
    run: CounterRun
    depth = max((e.dims[1] for e in draft.catalog.of_type("CounterTop") if e.dims[1] < 0.9), default=0.6)
    for run in shell.fixtures.counters:
        wall = walls[run.wall]
        # a run that starts or ends at a corner leaves the perpendicular run's depth free; our
        # counters may be a little deeper than the plan's depth
        extra = max(0.0, depth - run.depth) + GAP + 0.01
        u = run.start + (extra if run.start > 1e-6 else 0.0)
        end = run.end - (extra if run.end < wall.length - 1e-6 else 0.0)
        for slot in sorted(slots_in.get(run.id, []), key=lambda s: s.offset):
            if slot.type == "Sink":
                _tile_counter(draft, wall, u, slot.offset)
                sink = _pick_sink(draft, slot.width)
                u = slot.offset + slot.width
                if sink is not None:
                    start = slot.offset + max(0.0, (slot.width - _width(sink)) / 2)
                    host = _add_against(draft, wall, sink, start)
                    _add_anchors(draft, host, sink)
                    u = max(u, start + _width(sink))  # a sink wider than its slot pushes the next counter along
            elif slot.type == "StoveBurner":
                _tile_counter(draft, wall, u, slot.offset)
                top = _stove_counter(draft, wall, slot)
                if top is not None:
                    _stove(draft, wall, slot, top.position[2] + draft.catalog.get(top.asset).bbox_max[2], run.depth,
                           top.id)
                    u = slot.offset + _width(draft.catalog.get(top.asset))
                else:
                    u = slot.offset + slot.width
        _tile_counter(draft, wall, u, end)
    for slot in shell.fixtures.slots:
        if slot.counter:
            continue
        wall = walls[slot.wall]
        entry = draft.pick_variant(slot.type, lambda e, w=slot.width: _width(e) <= w + 0.05)
        if entry is None:
            continue
        host = _add_against(draft, wall, entry, slot.offset + max(0.0, (slot.width - _width(entry)) / 2))
        _add_anchors(draft, host, entry)
