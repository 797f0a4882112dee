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


def _stove(draft: SceneDraft, wall: Wall, slot: FixtureSlot, counter_top: float, depth: float,
           host: str | None) -> None:
    burner = draft.pick_variant("StoveBurner")
    knob = draft.pick_variant("StoveKnob")
    if burner is None:
        return
    yaw = math.atan2(-wall.normal[0], wall.normal[1])
    mid = slot.offset + slot.width / 2
    for du in (-0.17, 0.17):
        for dv in (0.17, 0.42):
            x, y = wall.point(mid + du - (burner.bbox_min[0] + burner.bbox_max[0]) / 2, GAP + dv)
            draft.add(burner, x, y, counter_top - burner.bbox_min[2], yaw, "fixture", True, parent=host)
            if knob is not None and dv == 0.17:
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
    for run in shell.fixtures.counters:
        wall = walls[run.wall]
        u = run.start
        for slot in sorted(slots_in.get(run.id, []), key=lambda s: s.offset):
            if slot.type == "Sink":
                _tile_counter(draft, wall, u, slot.offset)
                sink = draft.pick_variant("Sink", lambda e, w=slot.width: _width(e) <= w + 1e-6) or min(
                    draft.catalog.of_type("Sink"), key=_width, default=None)
                if sink is not None:
                    host = _add_against(draft, wall, sink, slot.offset + (slot.width - _width(sink)) / 2)
                    _add_anchors(draft, host, sink)
                u = slot.offset + slot.width
            elif slot.type == "StoveBurner":
                under = _tile_counter(draft, wall, u, slot.offset + slot.width)
                _stove(draft, wall, slot, _counter_top_height(draft), run.depth, under[-1].id if under else None)
                u = slot.offset + slot.width
        _tile_counter(draft, wall, u, run.end)
    for slot in shell.fixtures.slots:
        if slot.counter:
            continue
        wall = walls[slot.wall]
        entry = draft.pick_variant(slot.type, lambda e, w=slot.width: _width(e) <= w + 0.05)
        if entry is None:
            continue
        host = _add_against(draft, wall, entry, slot.offset + max(0.0, (slot.width - _width(entry)) / 2))
        _add_anchors(draft, host, entry)
