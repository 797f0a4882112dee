"""Freezing a split: draw its episodes, layout by layout, until it holds the paper's count of each task type,
and write the result (the split's manifest, shipped in `luminous_sim/benchmark/data/`).

Per task type, the layouts ALFRED generates it in share its count: round robin over the layouts that still
hold a task not yet in the split (`counts.allocate`, from each layout's number of distinct tasks,
`planning.distinct_tasks`), and only once every layout is out of distinct tasks, repeats (the same task from
another start). In a layout, draws `0, 1, ...` (each from its own seed, `draw.draw_seed`) are taken in order;
a draw is rejected when no task fits (`no_task`), when it repeats a task of the split while the layout still
holds another (`duplicate`), or when the oracle does not solve it (`oracle`; the task is not drawn again in
that layout). Every rejection is counted per type and cause (the filter's before and after). A layout that
falls short (the oracle failed too often) passes its shortfall to the others.

Run by maintainers (`python -m luminous_sim.episodes.freeze --split U+ --workers 2`); a changed generator
that changes a split's episodes needs a new `SPLIT_VERSION` and a new freeze, never a silent change.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections import Counter
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from luminous_sim.benchmark.counts import PAPER_COUNTS, Layout, allocate, type_counts, type_layouts
from luminous_sim.benchmark.draw import Draw, draw, draw_seed, scene_of
from luminous_sim.benchmark.frozen import DATA_DIR, FROZEN_FORMAT, SPLIT_VERSION, manifest_path
from luminous_sim.benchmark.key import start_fields
from luminous_sim.episodes.expert_proof import solve
from luminous_sim.episodes.goals import TaskGoal
from luminous_sim.episodes.initial_state import FreshWorlds, alfred_set_up
from luminous_sim.episodes.spec import EpisodeSpec
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.scene import Scene
from luminous_sim.splits import plus_split
from luminous_sim.vocab import ALFRED_TASK_TYPES
from luminous_sim.world import World

REJECTIONS = ("layout", "no_task", "duplicate", "oracle")
DRAWS_PER_EPISODE = 60
"""A layout stops after this many draws per episode it owes (plus `DRAWS_SPARE`) and passes on what is left."""
DRAWS_SPARE = 200
ORACLE_FAILURES_IN_A_ROW = 6
"""A layout whose oracle fails this many different tasks in a row gives up (e.g. an appliance the agent cannot see
into) and passes what it owes on: each failure can cost a minute of pose search."""


def _params_key(params: dict[str, Any]) -> str:
    return json.dumps(params, sort_keys=True)


@dataclass(frozen=True)
class Capacity:
    """How many distinct tasks of a type a layout holds (0, with a cause and why, for none)."""

    task_type: str
    layout: Layout
    distinct: int
    cause: str = ""
    """For none: `layout` (the room cannot be generated) or `no_task` (it holds no task of the type)."""
    why: str = ""


def oracle_cause(scene: Scene, drawn: Draw) -> str:
    """Why the oracle does not solve a drawn episode from its start (`episodes.solve`'s cause, its plan not
    replayed: a plan that met the goal counts, as ALFRED's generator counts it); "" when it solves it."""
    spec = EpisodeSpec(scene, TaskGoal(drawn.task), drawn.dirty, start=drawn.start)
    return solve(spec, FreshWorlds(), replay=False).cause


def capacity(task_type: str, layout: Layout) -> Capacity:
    """`Capacity` of one (type, layout)."""
    from luminous_sim.planning import distinct_tasks
    from luminous_sim.tasks import TaskSamplingError

    try:
        scene = scene_of(layout)
    except InfeasibleSceneError as exc:
        return Capacity(task_type, layout, 0, "layout", str(exc))
    world = World(scene)
    try:
        alfred_set_up(world, task_type)
        return Capacity(task_type, layout, len(distinct_tasks(scene, world.view(), task_type)))
    except TaskSamplingError as exc:
        return Capacity(task_type, layout, 0, "no_task", str(exc))
    finally:
        world.close()


@dataclass
class Stream:
    """What a layout's draws gave one task type: episodes accepted in draw order, rejections by cause."""

    task_type: str
    layout: Layout
    need: int
    entries: list[dict[str, Any]] = field(default_factory=list)
    rejected: Counter[str] = field(default_factory=Counter)
    oracle_causes: Counter[str] = field(default_factory=Counter)
    draws: int = 0
    gave_up: bool = False
    """The oracle failed `ORACLE_FAILURES_IN_A_ROW` different tasks in a row here."""

    @property
    def exhausted(self) -> bool:
        """The draws ran out before the layout gave all it owed."""
        return len(self.entries) < self.need


def run_stream(split: str, task_type: str, layout: Layout, need: int) -> Stream:
    """Draw in `layout` until `need` episodes of `task_type` are accepted (or the draws run out)."""
    from luminous_sim.planning import distinct_tasks
    from luminous_sim.tasks import TaskSamplingError

    out = Stream(task_type, layout, need)
    if need == 0:
        return out
    code, ti = plus_split(split).code, ALFRED_TASK_TYPES.index(task_type)
    scene = scene_of(layout)
    world = World(scene)
    try:
        dirty = alfred_set_up(world, task_type)
        distinct = {_params_key(p.to_json()) for p in distinct_tasks(scene, world.view(), task_type)}
        accepted: set[str] = set()
        failed: set[str] = set()
        keys: set[str] = set()
        in_a_row = 0
        while len(out.entries) < need and out.draws < DRAWS_PER_EPISODE * need + DRAWS_SPARE:
            if in_a_row >= ORACLE_FAILURES_IN_A_ROW:
                out.gave_up = True
                break
            seed = draw_seed(code, ti, layout, out.draws)
            out.draws += 1
            try:
                drawn = draw(scene, world, task_type, seed, dirty)
            except TaskSamplingError:
                out.rejected["no_task"] += 1
                continue
            p = _params_key(drawn.task.params.to_json())
            distinct.add(p)
            if p in failed:
                out.rejected["oracle"] += 1
                continue
            repeat = p in accepted
            if drawn.key in keys or (repeat and distinct - accepted - failed):
                out.rejected["duplicate"] += 1
                continue
            cause = oracle_cause(scene, drawn)
            if cause:
                failed.add(p)
                in_a_row += 1
                out.rejected["oracle"] += 1
                out.oracle_causes[cause] += 1
                continue
            in_a_row = 0
            accepted.add(p)
            keys.add(drawn.key)
            out.entries.append({
                "task_type": task_type, "floor_plan": layout.floor_plan, "room_type": layout.room_type,
                "layout": layout.layout, "layout_seed": layout.layout_seed, "draw": out.draws - 1, "task_seed": seed,
                "pddl_params": drawn.task.params.to_json(), "start": start_fields(drawn.start), "repeat": repeat,
                "episode_key": drawn.key,
            })
    finally:
        world.close()
    return out


def _capacity_job(args: tuple[str, Layout]) -> Capacity:
    return capacity(*args)


def _stream_job(args: tuple[str, str, Layout, int]) -> Stream:
    return run_stream(*args)


def _interleave(groups: Sequence[Sequence[dict[str, Any]]]) -> list[dict[str, Any]]:
    """Round robin over the groups (each in its own order) until all are empty."""
    out: list[dict[str, Any]] = []
    depth = max((len(g) for g in groups), default=0)
    for k in range(depth):
        out.extend(g[k] for g in groups if k < len(g))
    return out


def _done_types(checkpoint: Path | None, split: str) -> dict[str, Any]:
    """What an interrupted freeze of `split` finished (its checkpoint's types), or nothing."""
    if checkpoint is None or not checkpoint.is_file():
        return {"per_type": {}, "stats": {}}
    data = json.loads(checkpoint.read_text())
    if data.get("split") != split or data.get("version") != SPLIT_VERSION:
        return {"per_type": {}, "stats": {}}
    return data


def freeze(split: str, workers: int = 1, log: Callable[[str], None] = print,
           checkpoint: Path | None = None) -> dict[str, Any]:
    """Draw split `split` and return its manifest (`{"header": ..., "entries": [...]}`); with `checkpoint`, each
    finished task type is saved there, and a freeze run again goes on from the types it holds."""
    from luminous_sim.fileio import write_atomic

    t0 = time.perf_counter()
    counts = type_counts(split)
    done = _done_types(checkpoint, split)
    pool = ProcessPoolExecutor(workers) if workers > 1 else None
    run: Callable[..., Any] = pool.map if pool is not None else map
    try:
        pairs = [(t, lay) for t in ALFRED_TASK_TYPES for lay in type_layouts(split, t)]
        caps = list(run(_capacity_job, pairs))
        log(f"{split}: capacities of {len(pairs)} (type, layout) pairs in {time.perf_counter() - t0:.0f} s")
        per_type: dict[str, list[dict[str, Any]]] = {}
        stats: dict[str, Any] = {}
        for t in ALFRED_TASK_TYPES:
            if t in done["per_type"]:
                per_type[t], stats[t] = done["per_type"][t], done["stats"][t]
                log(f"{split} {t}: {len(per_type[t])} from the checkpoint")
                continue
            mine = [c for c in caps if c.task_type == t]
            shares = allocate([c.distinct for c in mine], counts[t])
            streams = list(run(_stream_job, [(split, t, c.layout, n) for c, n in zip(mine, shares, strict=True)]))
            spent: set[int] = set()  # layouts whose draws ran out: they have given all they can
            for _ in range(len(mine)):  # pass a shortfall on to the layouts that met their share
                spent |= {i for i, s in enumerate(streams) if s.exhausted}
                short = counts[t] - sum(len(s.entries) for s in streams)
                able = [i for i, s in enumerate(streams) if s.entries and i not in spent]
                if short <= 0 or not able:
                    break
                extra = allocate([1 if i in able else 0 for i in range(len(streams))], short)
                redo = [i for i, e in enumerate(extra) if e]
                again = list(run(_stream_job, [(split, t, mine[i].layout, streams[i].need + extra[i]) for i in redo]))
                for i, s in zip(redo, again, strict=True):
                    streams[i] = s
            per_type[t] = _interleave([s.entries for s in streams])
            rejected: Counter[str] = sum((s.rejected for s in streams), Counter())
            rejected["layout"] += sum(1 for c in mine if c.cause == "layout")
            causes: Counter[str] = sum((s.oracle_causes for s in streams), Counter())
            stats[t] = {
                "asked": counts[t], "built": len(per_type[t]), "layouts": len(mine),
                "layouts_without_task": [c.layout.name for c in mine if c.distinct == 0],
                "distinct_tasks": sum(c.distinct for c in mine), "draws": sum(s.draws for s in streams),
                "rejected": {r: rejected[r] for r in REJECTIONS},
                "oracle_causes": dict(causes.most_common(5)),
                "repeats": sum(e["repeat"] for e in per_type[t]),
                "layouts_given_up": [s.layout.name for s in streams if s.gave_up],
            }
            log(f"{split} {t}: {len(per_type[t])}/{counts[t]} in {time.perf_counter() - t0:.0f} s, "
                f"rejected {stats[t]['rejected']}, repeats {stats[t]['repeats']}")
            if checkpoint is not None:
                write_atomic(checkpoint, json.dumps({"split": split, "version": SPLIT_VERSION, "per_type": per_type,
                                                     "stats": stats}))
    finally:
        if pool is not None:
            pool.shutdown()
    entries = _interleave([per_type[t] for t in ALFRED_TASK_TYPES])
    for i, e in enumerate(entries):
        e["index"] = i
    from luminous_sim import __version__

    header = {"format": FROZEN_FORMAT, "split": split, "version": SPLIT_VERSION, "luminous_version": __version__,
              "entries": len(entries), "counts": {t: len(per_type[t]) for t in ALFRED_TASK_TYPES},
              "paper_counts": counts, "stats": stats, "seconds": round(time.perf_counter() - t0)}
    return {"header": header, "entries": entries}


def write_manifest(manifest: dict[str, Any], path: Path) -> None:
    """The manifest as JSON lines: the header, then one entry per line (atomically)."""
    from luminous_sim.fileio import write_atomic

    lines = [json.dumps(manifest["header"], sort_keys=True)]
    lines += [json.dumps(e, sort_keys=True) for e in manifest["entries"]]
    write_atomic(path, "\n".join(lines) + "\n")


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m luminous_sim.episodes.freeze", description=__doc__.split("\n")[0])
    parser.add_argument("--split", required=True, choices=sorted(PAPER_COUNTS))
    parser.add_argument("--workers", type=int, default=1, choices=range(1, 65), metavar="1..64")
    parser.add_argument("--out", type=Path, default=DATA_DIR, help="folder to write <split>.jsonl into")
    args = parser.parse_args(argv)
    path = manifest_path(args.split, args.out)
    checkpoint = path.with_name(path.name + ".partial")
    manifest = freeze(args.split, args.workers, log=lambda m: print(m, file=sys.stderr, flush=True),
                      checkpoint=checkpoint)
    write_manifest(manifest, path)
    checkpoint.unlink(missing_ok=True)
    print(f"{path}: {manifest['header']['entries']} episodes")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
