"""CSSG entry point: a CDF, a room and a seed give a validated Scene (or an InfeasibleSceneError).

Stages (each a function of its own): room structure and fixtures -> furniture (score fields) ->
objects on/in receptacles -> decorations on walls -> layout validation; a sample that fails
validation is redrawn with the next sub-seed, up to `attempts` times.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cdf.schema import ChallengeDefinition
from luminous_sim.cssg.attributes import check_assets, check_sizes
from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.objects import reserve_for_goal
from luminous_sim.cssg.requests import Request, requests_from_cdf
from luminous_sim.cssg.sample import Checkpoint, Sample
from luminous_sim.cssg.structure import fixture_types, place_fixtures
from luminous_sim.cssg.tables import generation_layer
from luminous_sim.cssg.validate import LayoutReport, check_layout, named, relation_checks
from luminous_sim.errors import CDFError, InfeasibleSceneError
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Scene

ATTEMPTS = 20


@dataclass(frozen=True)
class Generated:
    scene: Scene
    report: LayoutReport


FIXTURE_DRAWS = 8
"""Shells drawn at most to find one whose fixtures include every fixture type the CDF names."""


def choose_room(cdf: ChallengeDefinition, rng: np.random.Generator, catalog: Catalog | None = None) -> RoomShell:
    """The CDF's room: a named library room, or a procedural shell of its room type meeting its constraints.

    A procedural shell should also hold the fixtures the CDF names (a bathroom with a counter when it
    asks for a CounterTop): of the first FIXTURE_DRAWS shells that meet the constraints, the first
    that does, else the first of them.
    """
    from luminous_sim.rooms.generate import generate_shell

    room = cdf.scene.room
    room_type = cdf.scene.room_type[int(rng.integers(len(cdf.scene.room_type)))]
    if isinstance(room, str):
        from luminous_sim.rooms.library import shell_for

        return shell_for(room, rng)
    wanted = {o.type for o in cdf.scene.objects if generation_layer(o.type) == "fixture"}
    meeting: list[RoomShell] = []
    for _ in range(200):
        shell = generate_shell(room_type, rng, shape=getattr(room, "shape", None))
        if room is not None and not _meets(shell, room):
            continue
        if not wanted or wanted <= fixture_types(shell, catalog or default_catalog()):
            return shell
        meeting.append(shell)
        if len(meeting) == FIXTURE_DRAWS:
            return meeting[0]
    if meeting:
        return meeting[0]
    raise InfeasibleSceneError(f"no {room_type} room shell meets the CDF's room constraints {room}")


def start_outside(cdf: ChallengeDefinition, shell: RoomShell) -> str | None:
    """Why the CDF's agent start (task.agent.position) is not on the room's floor, or None when it is or is unset."""
    from shapely.geometry import Point

    agent = cdf.task.agent if cdf.task is not None else None
    if agent is None or agent.position is None:
        return None
    x, y = agent.position
    if shell.house is not None:
        return _outside_rooms(x, y, shell)
    if shell.polygon().contains(Point(x, y)):
        return None
    minx, miny, maxx, maxy = shell.bounds
    return (f"({x:g}, {y:g}) is outside room {shell.name!r} (x {minx:g}..{maxx:g}, y {miny:g}..{maxy:g} m); "
            "expected a start inside its floor outline")


def _outside_rooms(x: float, y: float, shell: RoomShell) -> str | None:
    """Why (x, y) lies on no room's floor of a house (in a wall, or outside), or None when it does."""
    from shapely.geometry import Point

    assert shell.house is not None
    if any(r.polygon().contains(Point(x, y)) for r in shell.house.rooms):
        return None
    rooms = "; ".join(f"{r.name} x {b[0]:g}..{b[2]:g}, y {b[1]:g}..{b[3]:g}"
                      for r in shell.house.rooms for b in [r.polygon().bounds])
    return (f"({x:g}, {y:g}) is on no room's floor of house {shell.name!r} (its rooms: {rooms} m); expected a "
            "start inside a room, in house coordinates")


def _fixed_room(cdf: ChallengeDefinition) -> bool:
    """Whether the CDF names a library room (the same shell on every attempt, unlike a procedural one)."""
    from luminous_sim.rooms.library import is_procedural

    return isinstance(cdf.scene.room, str) and not is_procedural(cdf.scene.room)


def _meets(shell: RoomShell, c) -> bool:
    minx, miny, maxx, maxy = shell.bounds
    width = min(maxx - minx, maxy - miny)
    return ((c.min_area is None or shell.area >= c.min_area) and (c.max_area is None or shell.area <= c.max_area)
            and (c.min_width is None or width >= c.min_width) and (c.max_width is None or width <= c.max_width))


BACKTRACKS = 3
"""Times one sample may go back and re-place the anchor of a piece that could not meet its relations."""


def sample_layout(cdf: ChallengeDefinition, shell: RoomShell, rng: np.random.Generator, catalog: Catalog,
                  attempt: int) -> tuple[SceneDraft, LayoutReport]:
    """One CSSG sample and its validation report.

    Requests are placed in order; when a piece of furniture cannot meet a hard relation to an anchor
    placed earlier in this sample, the sample goes back to just before that anchor and draws it again
    (at most BACKTRACKS times), so that an anchor drawn into a corner does not doom its dependents.
    An anchor bound to one of the room's own fixtures is not drawn, so it is never gone back to.
    A sample stops at the first failure that no backtrack can undo (its report covers what was placed).
    """
    draft = SceneDraft(shell, catalog, rng)
    place_fixtures(draft)
    requests = requests_from_cdf(cdf, shell.room_type, rng, area=shell.area, fixtures=_fixtures(draft))
    sample = Sample.start(draft)
    checkpoints: dict[str, Checkpoint] = {}
    backtracks = 0
    undo_floor = _undo_floors(requests)
    reserved: int | None = None  # where room was kept for the goal's puts (before the room's own objects)
    i = 0
    while i < len(requests):
        req = requests[i]
        if req.layer == "object" and not req.explicit and reserved is None:
            reserve_for_goal(draft, requests, sample.by_name, sample.occupied)
            reserved = i
        if req.layer in ("furniture", "fixture"):
            checkpoints[req.name] = sample.checkpoint(i)
        ok = sample.place(req)
        if not ok and backtracks < BACKTRACKS and req.layer in ("furniture", "fixture"):
            # an anchor bound to the room's own fixture would be bound again just the same
            anchors = [r.anchor for r in req.rels
                       if r.explicit and r.hard and r.anchor in checkpoints and r.anchor not in sample.bound]
            if anchors:
                cp = checkpoints[anchors[0]]
                sample.restore(cp)
                if reserved is not None and cp.index <= reserved:
                    reserved = None
                backtracks += 1
                i = cp.index
                continue
        if not ok and req.name not in sample.by_name:
            sample.unplaced.append(req.name)
        if not ok and (backtracks >= BACKTRACKS or undo_floor[i] > i) and _fails_for_good(req, sample):
            return draft, check_layout(draft, requests[:i + 1], sample.ctx, sample.unplaced, attempt,
                                       stopped_after=req.name)
        i += 1
    report = check_layout(draft, requests, sample.ctx, sample.unplaced, attempt)
    report.ignored_attributes = {r.name: sorted(r.attributes) for r in requests
                                 if r.name in sample.bound and r.attributes}
    return draft, report


def _fixtures(draft: SceneDraft) -> frozenset[str]:
    """Types of the fixtures the room already has (for rules about them: stools at the counter)."""
    return frozenset(p.obj.type for p in draft.placed if p.obj.layer == "fixture")


def _undo_floors(requests: list[Request]) -> list[float]:
    """Per request, the earliest request a later backtrack could go back to (inf: none can): a failure that
    no backtrack can undo is final."""
    index = {r.name: k for k, r in enumerate(requests)}
    floors: list[float] = [float("inf")] * len(requests)
    lowest = float("inf")
    for j in range(len(requests) - 1, -1, -1):
        floors[j] = lowest
        req = requests[j]
        if req.layer in ("furniture", "fixture"):
            for r in req.rels:
                k = index.get(r.anchor or "")
                if r.explicit and r.hard and k is not None and k < j and requests[k].layer in ("furniture", "fixture"):
                    lowest = min(lowest, k)
    return floors


def _fails_for_good(req: Request, sample: Sample) -> bool:
    """Whether a CDF object just placed (or not) already fails validation: left out, or one of its hard
    relations unmet, exactly as the final check would find it."""
    if not req.explicit:
        return False
    draft = sample.draft
    return req.name in sample.unplaced or any(c.explicit and c.hard and not c.met
                                              for c in relation_checks(req, named(draft), draft, sample.ctx))


def generate(cdf: ChallengeDefinition, seed: int = 0, room: RoomShell | None = None,
             catalog: Catalog | None = None, attempts: int = ATTEMPTS) -> Generated:
    """Sample layouts until one passes validation; the same inputs give the same scene, byte for byte."""
    if cdf.scene.house is not None:
        raise CDFError(f"CDF {cdf.name or ''}: scene.house describes a house of several rooms; expected "
                       "cssg.generate_house for it (generate makes one room)")
    catalog = catalog or default_catalog()
    check_assets(cdf, catalog)
    check_sizes(cdf, catalog)
    failures: Counter[str] = Counter()
    unplaced: set[str] = set()
    shell = room
    for attempt in range(attempts):
        rng = np.random.default_rng(np.random.SeedSequence([seed, attempt]))
        if room is None:
            shell = choose_room(cdf, rng, catalog)
        if attempt == 0 and (room is not None or _fixed_room(cdf)):
            outside = start_outside(cdf, shell)
            if outside:
                raise InfeasibleSceneError(f"CDF{' ' + cdf.name if cdf.name else ''}: task.agent.position: {outside}")
        draft, report = sample_layout(cdf, shell, rng, catalog, attempt)
        if report.ok:
            scene = draft.to_scene("cssg", seed, source=cdf.name or "", notes={"attempt": attempt,
                                                                               "unplaced": report.unplaced})
            return Generated(scene, report)
        failures.update(report.failed_relations())
        failures.update(f"{n} could not be placed" for n in report.unplaced if n in report.required)
        unplaced.update(n for n in report.unplaced if n in report.required)
        failures.update(f"{o} is out of the agent's reach" for o in report.unreachable)
        failures.update(f"{a} overlaps {b}" for a, b in report.overlaps)
    worst = "; ".join(f"{k} ({v}/{attempts})" for k, v in failures.most_common(6)) or "no valid sample"
    raise InfeasibleSceneError(f"CDF {cdf.name or ''!s}: no valid layout in {attempts} samples: {worst}",
                               unplaced=tuple(sorted(unplaced)))
