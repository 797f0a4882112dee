"""Scene-synthesis methods compared on the same rooms and the same embodied tasks (issue 19; used by
bench_cssg.py --methods ...).

Methods (`METHODS`): `cssg` (cssg.generate, empty CDF of the room type), `uniform` (the uniform-random
baseline, never resampled), `learned` (the learned layout model, repaired and furnished by `layouts.realize`),
and the imported layouts `front` (the hand-written 3D-FRONT kitchen fixture) and `atiss` (the ATISS bedroom
fixture), realized with the seed as the object layer's seed. cssg, uniform and learned furnish the same
procedural room per room type and seed (`generate_shell(room_type, default_rng(seed))`); the imported ones
bring their own room and serve their own room type only.

Per method and room type: layouts accepted (valid, as each method's own check says: CSSG's resampling
ends in a valid one or in none; the baseline's report; `realize`'s acceptance), pieces the repair moved and
left out, scenes with footprint overlaps, objects out of the agent's reach, CSSG's implicit rules met
(scored the same way on every scene, `implicit_rules`), PyBullet settling (interpenetrations, moved,
fell), the median seconds per scene. Then the oracle's success per ALFRED task type: for episode i of a
type, seed i's scene of the i-th room type (in turn) that the type is generated in and the method serves;
a scene in which no task of the type can be drawn counts as a failure ("no task").
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cssg import Generated, LayoutReport, empty_cdf, generate, sample_uniform
from luminous_sim.errors import LuminousError
from luminous_sim.layouts import Layout
from luminous_sim.rooms import generate_shell
from luminous_sim.scene import Scene
from luminous_sim.vocab import ROOM_TYPES

FIXTURES = Path(__file__).resolve().parents[1] / "tests" / "layouts" / "fixtures"


@dataclass
class Outcome:
    """One method's scene for one room type and seed (scene None: the method gave none)."""

    scene: Scene | None
    report: LayoutReport | None
    accepted: bool
    seconds: float
    moved: int = 0
    left_out: int = 0
    furniture: int = 0
    distances: tuple[float, ...] = ()
    """metres each moved piece was moved."""


@dataclass(frozen=True)
class Method:
    name: str
    room_types: tuple[str, ...]
    make: Callable[[str, int], Outcome]


@cache
def _shell(room_type: str, seed: int):
    return generate_shell(room_type, np.random.default_rng(seed))


def _floor_count(scene: Scene) -> int:
    return sum(1 for o in scene.objects if o.parent is None and o.layer == "furniture")


def _cssg(room_type: str, seed: int) -> Outcome:
    t0 = time.perf_counter()
    try:
        g = generate(empty_cdf(room_type), seed=seed, room=_shell(room_type, seed), catalog=default_catalog())
    except LuminousError:
        return Outcome(None, None, False, time.perf_counter() - t0)
    return Outcome(g.scene, g.report, True, time.perf_counter() - t0, furniture=_floor_count(g.scene))


def _uniform(room_type: str, seed: int) -> Outcome:
    t0 = time.perf_counter()
    rng = np.random.default_rng(np.random.SeedSequence(seed))  # as cssg.generate_uniform draws
    draft, report = sample_uniform(empty_cdf(room_type), _shell(room_type, seed), rng, default_catalog())
    g = Generated(draft.to_scene("uniform", seed), report)
    return Outcome(g.scene, g.report, report.ok, time.perf_counter() - t0, furniture=_floor_count(g.scene))


def _realized(layout_of: Callable[[int], Layout], seed: int) -> Outcome:
    from luminous_sim.layouts import realize

    t0 = time.perf_counter()
    r = realize(layout_of(seed), seed)
    g = r.given.generated
    actions = [x.action for x in r.given.repairs]
    return Outcome(g.scene, g.report, r.ok, time.perf_counter() - t0, actions.count("moved"),
                   actions.count("left_out") + len(r.unmatched), _floor_count(g.scene),
                   tuple(x.distance for x in r.given.repairs if x.action == "moved"))


@cache
def _learned_generator():
    from luminous_sim.layouts import LearnedLayouts
    from luminous_sim.layouts.learned import load_model

    load_model()  # loaded once, before any scene is timed
    return LearnedLayouts()


def _learned(room_type: str, seed: int) -> Outcome:
    return _realized(lambda s: _learned_generator().layout(_shell(room_type, s), s), seed)


@cache
def _imported(kind: str):
    from luminous_sim import layouts

    if kind == "front":
        return layouts.import_front(FIXTURES / "front_kitchen.json", model_info=FIXTURES / "front_model_info.json")
    return layouts.import_atiss(FIXTURES / "atiss_bedroom.json")


METHODS: dict[str, Method] = {
    "cssg": Method("cssg", tuple(ROOM_TYPES), _cssg),
    "uniform": Method("uniform", tuple(ROOM_TYPES), _uniform),
    "learned": Method("learned", tuple(ROOM_TYPES), _learned),
    "front": Method("front", ("Kitchen",), lambda rt, s: _realized(lambda _: _imported("front"), s)),
    "atiss": Method("atiss", ("Bedroom",), lambda rt, s: _realized(lambda _: _imported("atiss"), s)),
}
"""Every method the comparison knows, by name (add one here to compare it)."""


def implicit_rules(scene: Scene, catalog: Catalog) -> tuple[int, int]:
    """(met, applicable) of CSSG's implicit floor rules (cssg/data/implicit_rules.json) in any scene, scored as
    CSSG's validation scores them: each free-standing piece of a rule's subject type, against the best of
    the pieces of its target type (a rule whose target type is absent, or an `unless` type present, does
    not apply)."""
    from luminous_sim.cdf import STRUCTURE_ELEMENTS
    from luminous_sim.cssg.draft import Placed, SceneDraft
    from luminous_sim.cssg.furniture import FloorContext, register
    from luminous_sim.cssg.requests import implicit_table
    from luminous_sim.cssg.scores import TOLERANCE
    from luminous_sim.scene import footprint

    draft = SceneDraft(scene.room, catalog, np.random.default_rng(0))
    for o in scene.objects:
        entry = catalog.for_object(o)
        draft.placed.append(Placed(o, entry, footprint(entry, o.position[0], o.position[1], o.yaw)))
    ctx = FloorContext.create(draft)
    floor = [p for p in draft.placed if p.obj.parent is None]
    for p in floor:
        register(ctx, p.obj.id, p.obj, p.entry)
    types = {p.obj.type for p in floor}
    met = total = 0
    for rule in implicit_table()["rules"]:
        if rule["relation"] not in TOLERANCE or types & set(rule.get("unless", ())):
            continue
        target = rule.get("target")
        if target is None or target in STRUCTURE_ELEMENTS:
            anchors: list[str | None] = [target]
        else:
            anchors = [p.obj.id for p in floor if p.obj.type == target]
            if not anchors:
                continue
        for p in (q for q in floor if q.obj.type == rule["subject"]):
            x, y, yaw = p.obj.position[0], p.obj.position[1], p.obj.yaw
            total += 1
            met += any(ctx.check(rule["relation"], p.entry, a, x, y, yaw)[0] for a in anchors if a != p.obj.id)
    return met, total


@dataclass
class Tally:
    outcomes: list[Outcome] = field(default_factory=list)
    rules: list[tuple[int, int]] = field(default_factory=list)
    physics: list = field(default_factory=list)


def _rate(hits: int, total: int) -> str:
    return f"{100 * hits / total:.0f}% ({hits}/{total})" if total else "n/a"


def _spread(xs: list[float]) -> str:
    if not xs:
        return "n/a"
    q = np.percentile(xs, [25, 75]) if len(xs) > 1 else (xs[0], xs[0])
    return f"{statistics.median(xs):.2f} [{q[0]:.2f}-{q[1]:.2f}]"


def layout_rows(t: Tally) -> dict[str, str]:
    """The table's rows for one method and room type."""
    got = [o for o in t.outcomes if o.scene is not None]
    reach_total = sum(sum(1 for x in o.scene.objects if x.layer != "decoration") for o in got if o.scene)
    rows = {
        "layouts accepted (valid)": _rate(sum(o.accepted for o in t.outcomes), len(t.outcomes)),
        "free-standing furniture (mean)": f"{np.mean([o.furniture for o in got]):.1f}" if got else "n/a",
        "pieces moved by repair (mean)": f"{np.mean([o.moved for o in got]):.1f}" if got else "n/a",
        "metres moved, median [IQR]": _spread([d for o in got for d in o.distances]),
        "pieces left out (mean)": f"{np.mean([o.left_out for o in got]):.1f}" if got else "n/a",
        "scenes with overlaps": _rate(sum(bool(o.report and o.report.overlaps) for o in got), len(got)),
        "objects out of reach": _rate(sum(len(o.report.unreachable) for o in got if o.report), reach_total),
        "implicit rules met": _rate(sum(m for m, _ in t.rules), sum(n for _, n in t.rules)),
        "seconds per scene, median [IQR]": _spread([o.seconds for o in got]),
    }
    if t.physics:
        rows["scenes interpenetrating >1cm"] = _rate(sum(bool(p.interpenetrations) for p in t.physics), len(t.physics))
        rows["objects moved >1cm settling"] = str(sum(len(p.moved) for p in t.physics))
        rows["objects fell settling"] = str(sum(len(p.fell) for p in t.physics))
    return rows


def _print_table(title: str, columns: dict[str, dict[str, str]]) -> None:
    names = list(columns)
    keys = list(dict.fromkeys(k for c in columns.values() for k in c))
    width = max(24, *(len(v) + 2 for c in columns.values() for v in c.values()))
    print(f"\n== {title} ==")
    print(f"{'':34}" + "".join(f"{n:>{width}}" for n in names))
    for k in keys:
        print(f"{k:34}" + "".join(f"{columns[n].get(k, '-'):>{width}}" for n in names))


def episodes(method: Method, task_type: str, count: int,
             scene_of: Callable[[str, int], Outcome]) -> tuple[int, int, int]:
    """(successes, episodes, scenes without such a task) of the oracle over `count` episodes."""
    from luminous_sim.episode import run_episode
    from luminous_sim.tasks import TASK_TYPES
    from luminous_sim.tasks.errors import TaskSamplingError

    rooms = [rt for rt in method.room_types if rt in TASK_TYPES[task_type].rooms]
    if not rooms:
        return 0, 0, 0
    ok = no_task = 0
    for i in range(count):
        outcome = scene_of(rooms[i % len(rooms)], i)
        if outcome.scene is None:
            continue
        try:
            ok += run_episode(outcome.scene, task_type, i, record_frames=False, extra_annotations=0)[0].success
        except TaskSamplingError:  # no task of this type in the scene: a failure of the scene
            no_task += 1
    return ok, count, no_task


def compare(names: list[str], room_types: list[str], n: int, n_episodes: int, physics: bool) -> None:
    """Print the comparison tables (layouts per room type over seeds 0..n-1; episodes per task type)."""
    from luminous_sim.tasks import TASK_TYPES

    unknown = [m for m in names if m not in METHODS]
    if unknown:
        raise SystemExit(f"--methods: unknown {', '.join(unknown)} (known: {', '.join(METHODS)})")
    methods = [METHODS[m] for m in names]
    catalog = default_catalog()
    scenes: dict[tuple[str, str, int], Outcome] = {}

    def scene_of(method: Method) -> Callable[[str, int], Outcome]:
        def get(room_type: str, seed: int) -> Outcome:
            key = (method.name, room_type, seed)
            if key not in scenes:
                scenes[key] = method.make(room_type, seed)
            return scenes[key]
        return get

    for room_type in room_types:
        columns = {}
        for m in (m for m in methods if room_type in m.room_types):
            t = Tally()
            for seed in range(n):
                o = scene_of(m)(room_type, seed)
                t.outcomes.append(o)
                if o.scene is None:
                    continue
                t.rules.append(implicit_rules(o.scene, catalog))
                if physics:
                    from luminous_sim.world.physics_check import check_physics

                    t.physics.append(check_physics(o.scene))
            columns[m.name] = layout_rows(t)
        _print_table(f"{room_type}: empty CDF, {n} seeds (procedural rooms; imported layouts in their own room)",
                     columns)
    if n_episodes <= 0:
        return
    counts = {m.name: {t: episodes(m, t, n_episodes, scene_of(m)) for t in TASK_TYPES} for m in methods}
    columns = {}
    for name, per_type in counts.items():
        columns[name] = {t: _rate(ok, total) + (f", {no_task} no task" if no_task else "") if total else "-"
                         for t, (ok, total, no_task) in per_type.items()}
        columns[name]["all task types"] = _rate(sum(c[0] for c in per_type.values()),
                                                sum(c[1] for c in per_type.values()))
    _print_table(f"oracle success per task type ({n_episodes} episodes per type and method)", columns)
