"""Oracle figures in the layout of the paper's Table 2: success per task type over sampled tasks in
generated scenes, before and after the feasibility filter, subgoal success per subgoal type, median
planning time, and low-level trajectory length per type next to ALFRED's (spec 2.3, train means).

    python benchmarks/bench_oracle.py --n 50 --jobs 2   # the issue's figure (about 10 s per slot)
    python benchmarks/bench_oracle.py --n 5

Rooms are default rooms of a room type the task type allows; where none of three holds a task of the
type that fits physically (two of a kind for pick_two, room in the receptacle), a room is generated for a
drawn task ('for task' column). 'no task' counts slots where no such room was found (no scene: neither
population has a task there).

Two populations of tasks share each slot's scene:

- 'as sampled' (the paper's Table 2 counts these): the sampler's raw draw, `tasks.sample_task` over the
  scene's whole state (as `run_episode` sets the world up: for cleaning, everything dirty), with the
  slot's task stream; no object left out as unseeable, no `physically_feasible` filter, solved by the
  oracle once with no redraw (`episode.run_task`).
- 'after filter' (today's figure): `episode.run_episode`, whose `planning.draw_task` leaves out objects
  seen from no reachable pose and keeps only tasks whose put has a free, stable spot
  (`physically_feasible`), and which redraws a task after a failure that blames the task.

'removed' counts raw draws the filter would not have kept (`filter_verdict`: the filter's tests for one
task), with their success beside it.

Every episode is appended to a JSON-lines file (--out) as it finishes; a rerun with the same file
skips the episodes already there, so a long run can be stopped and resumed.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from collections import Counter, defaultdict
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ALFRED_MEAN_LENGTH = {"pick_and_place_simple": 29.9, "pick_two_obj_and_place": 60.9, "look_at_obj_in_light": 37.7,
                      "pick_clean_then_place_in_recep": 44.6, "pick_heat_then_place_in_recep": 62.5,
                      "pick_cool_then_place_in_recep": 59.0, "pick_and_place_with_movable_recep": 51.2}
ROOMS = {"pick_and_place_simple": ["Kitchen", "LivingRoom", "Bedroom", "Bathroom"],
         "pick_two_obj_and_place": ["Kitchen", "LivingRoom", "Bedroom", "Bathroom"],
         "look_at_obj_in_light": ["LivingRoom", "Bedroom"], "pick_clean_then_place_in_recep": ["Kitchen", "Bathroom"],
         "pick_heat_then_place_in_recep": ["Kitchen"], "pick_cool_then_place_in_recep": ["Kitchen"],
         "pick_and_place_with_movable_recep": ["Kitchen", "LivingRoom", "Bedroom"]}


def filter_verdict(scene, view, task_type: str, params) -> str | None:
    """Why `planning.draw_task`'s filter would not keep the task of `params` in this world, or None: its
    objects must be seen from some reachable pose (`unseeable`) and its put must have a free, stable spot
    (`physically_feasible`), the tests `draw_task` applies to every candidate."""
    from luminous_sim.planning import physically_feasible, unseeable
    from luminous_sim.tasks import TaskSamplingError, feasible_params

    hidden = unseeable(view)
    try:
        seen = feasible_params(scene, view.state.without(hidden), task_type)
    except TaskSamplingError:
        seen = []
    if params not in seen:
        return "an object it needs is seen from no reachable pose"
    if not physically_feasible(view, params, hidden, two=task_type == "pick_two_obj_and_place"):
        return "no free, stable spot for its put"
    return None


def raw_episode(scene, task_type: str, k: int) -> dict:
    """The sampler's raw draw for slot `k` in `scene` (no filter), solved once by the oracle, and whether the
    feasibility filter would have kept it."""
    import numpy as np

    from luminous_sim.episode import prepared_world, run_task
    from luminous_sim.tasks import TaskSamplingError, sample_task

    rng = np.random.default_rng(np.random.SeedSequence([k, 11]))  # run_episode's task stream
    world = prepared_world(scene, task_type)
    try:
        view = world.view()
        task = sample_task(scene, view.state, task_type, rng)
        removed = filter_verdict(scene, view, task_type, task.params)
    except TaskSamplingError as exc:
        return {"sampled": False, "why": str(exc)}
    finally:
        world.close()
    r = run_task(scene, task, seed=k, record_frames=False)
    return {"sampled": True, "goal": r.goal, "success": r.success, "goal_conditions": list(r.goal_conditions),
            "failure": r.failure, "removed": removed}


def episode(task_type: str, k: int) -> dict:
    """Run task slot `k` of `task_type` in a generated room that supports such a task: the filtered draw
    (`run_episode`) and the raw one (`raw_episode`)."""
    from luminous_sim.data import scene_for_task
    from luminous_sim.episode import run_episode
    from luminous_sim.errors import LuminousError

    room = ROOMS[task_type][k % len(ROOMS[task_type])]
    seed = 1000 + k
    try:
        scene = scene_for_task(task_type, room, seed)
        t0 = time.perf_counter()
        r, record = run_episode(scene, task_type, seed=k, record_frames=False, extra_annotations=0)
        traj = record.trajectory
    except LuminousError as exc:  # no room of this type supports the task, or none fits physically
        return {"type": task_type, "k": k, "room": room, "scene_seed": seed, "success": None, "no_task": 1,
                "why": str(exc), "raw": {"sampled": False, "why": "no scene"}}
    raw = raw_episode(scene, task_type, k)
    ok_subgoals = [h["planner_action"]["action"] for h in traj.high_pddl if h["planner_action"]["action"] != "End"]
    return {"type": task_type, "k": k, "room": room, "scene_seed": seed, "task_driven": bool(scene.source),
            "goal": r.goal, "success": r.success,
            "goal_conditions": list(r.goal_conditions), "low_actions": r.low_actions,
            "planning_seconds": r.planning_seconds, "episode_seconds": time.perf_counter() - t0,
            "subgoals_ok": ok_subgoals, "subgoals_failed": traj.failed_subgoals, "failures": traj.failures,
            "replans": traj.replans, "no_task": 0, "raw": raw}


def _median(records: list[dict], key: str) -> float:
    return statistics.median(r[key] for r in records) if records else float("nan")


def _rate(ok: int, n: int) -> str:
    return f"{ok}/{n} ({100 * ok / n:.0f}%)" if n else "n/a"


def filter_table(by_type: dict[str, list[dict]], types: list[str]) -> None:
    """Success as sampled (before the filter) beside success after it, and what the filter removed."""
    print(f"{'task type':36}{'as sampled':>16}{'removed':>9}{'kept: ok':>15}{'removed: ok':>14}"
          f"{'after filter':>16}{'no task':>9}")
    tot = Counter()
    for t in types:
        rs = by_type[t]
        raw = [r["raw"] for r in rs if r["raw"]["sampled"]]
        removed = [x for x in raw if x["removed"]]
        kept = [x for x in raw if not x["removed"]]
        after = [r for r in rs if r["success"] is not None]
        row = Counter(raw=len(raw), raw_ok=sum(x["success"] for x in raw), removed=len(removed),
                      removed_ok=sum(x["success"] for x in removed), kept=len(kept),
                      kept_ok=sum(x["success"] for x in kept), after=len(after),
                      after_ok=sum(r["success"] for r in after), unsampled=len(rs) - len(raw))
        tot.update(row)
        print(f"{t:36}{_rate(row['raw_ok'], row['raw']):>16}{row['removed']:>9}"
              f"{_rate(row['kept_ok'], row['kept']):>15}{_rate(row['removed_ok'], row['removed']):>14}"
              f"{_rate(row['after_ok'], row['after']):>16}{row['unsampled']:>9}")
    print(f"{'all':36}{_rate(tot['raw_ok'], tot['raw']):>16}{tot['removed']:>9}"
          f"{_rate(tot['kept_ok'], tot['kept']):>15}{_rate(tot['removed_ok'], tot['removed']):>14}"
          f"{_rate(tot['after_ok'], tot['after']):>16}{tot['unsampled']:>9}")
    causes = Counter(r["raw"]["removed"] for t in types for r in by_type[t]
                     if r["raw"]["sampled"] and r["raw"]["removed"])
    if causes:
        print("\nwhy the filter removed a raw draw:")
        for why, n in causes.most_common():
            print(f"  {n:4d}  {why}")
    failed = [(r, r["raw"]) for t in types for r in by_type[t] if r["raw"]["sampled"] and not r["raw"]["success"]]
    if failed:
        print("\nraw draws the oracle failed (type, slot, goal: first cause):")
        for r, x in failed:
            print(f"  {r['type']} k={r['k']} {x['goal'][:80]}: {(x['failure'] or '')[:140]}")


def summarise(records: list[dict], types: list[str]) -> None:
    by_type = defaultdict(list)
    for r in records:
        by_type[r["type"]].append(r)
    print("success per task type, before and after the feasibility filter (slots as sampled):")
    filter_table(by_type, types)
    print("\nafter the filter (run_episode), in the layout of the paper's Table 2:")
    subgoal_ok, subgoal_all = Counter(), Counter()
    print(f"{'task type':36}{'success':>16}{'goal-cond.':>12}{'no task':>9}{'for task':>9}{'plan (med)':>12}"
          f"{'low actions':>13}{'ALFRED':>8}{'episode':>10}")
    total_ok = total_n = 0
    for t in types:
        rs = [r for r in by_type[t] if r["success"] is not None]
        skipped = sum(r["no_task"] for r in by_type[t])
        ok = sum(r["success"] for r in rs)
        done = sum(r["goal_conditions"][0] for r in rs)
        tot = sum(r["goal_conditions"][1] for r in rs)
        total_ok += ok
        total_n += len(rs)
        for r in rs:
            subgoal_all.update(r["subgoals_ok"] + r["subgoals_failed"])
            subgoal_ok.update(r["subgoals_ok"])
        mean_len = statistics.mean(r["low_actions"] for r in rs) if rs else float("nan")
        sr = f"{ok}/{len(rs)} ({100 * ok / len(rs):.0f}%)" if rs else "n/a"
        gc = f"{100 * done / tot:.0f}%" if tot else "n/a"
        driven = sum(r.get("task_driven", False) for r in rs)
        print(f"{t:36}{sr:>16}{gc:>12}{skipped:>9}{driven:>9}{1000 * _median(rs, 'planning_seconds'):>10.0f}ms"
              f"{mean_len:>13.1f}{ALFRED_MEAN_LENGTH[t]:>8.1f}{_median(rs, 'episode_seconds'):>9.1f}s")
    if total_n:
        print(f"{'all':36}{f'{total_ok}/{total_n} ({100 * total_ok / total_n:.1f}%)':>16}")
    print("\nsubgoal success (executed without failure / attempted):")
    for a in sorted(subgoal_all):
        print(f"  {a:16} {subgoal_ok[a]}/{subgoal_all[a]} ({100 * subgoal_ok[a] / subgoal_all[a]:.1f}%)")
    failed = [r for r in records if r["success"] is False]
    if failed:
        print("\nfailed episodes (type, slot, room, scene seed: last failure):")
        for r in failed:
            why = r["failures"][-1] if r["failures"] else f"goal conditions {r['goal_conditions']}"
            print(f"  {r['type']} k={r['k']} {r['room']} seed={r['scene_seed']}: {why}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=5, help="tasks per type")
    ap.add_argument("--types", nargs="*", default=list(ALFRED_MEAN_LENGTH))
    ap.add_argument("--jobs", type=int, default=1, help="worker processes")
    ap.add_argument("--out", type=Path, default=Path("out/bench/oracle.jsonl"), help="episode records (resumable)")
    ap.add_argument("--fresh", action="store_true", help="ignore records already in --out")
    args = ap.parse_args()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    if args.fresh and args.out.exists():
        args.out.unlink()
    records = [json.loads(line) for line in args.out.read_text().splitlines() if line.strip()] \
        if args.out.exists() else []
    records = [r for r in records if "raw" in r]  # older records lack the raw draw: run those again
    have = {(r["type"], r["k"]) for r in records}
    todo = [(t, k) for k in range(args.n) for t in args.types if (t, k) not in have]
    with args.out.open("a") as sink, ProcessPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(episode, t, k) for t, k in todo]
        for i, fut in enumerate(as_completed(futures), 1):
            rec = fut.result()
            sink.write(json.dumps(rec) + "\n")  # one line per episode: a stopped run loses at most one
            sink.flush()
            records.append(rec)
            print(f"[{i}/{len(todo)}] {rec['type']} k={rec['k']}: "
                  f"{'ok' if rec['success'] else 'FAILED' if rec['success'] is False else 'no task'}", flush=True)
    wanted = set(args.types)
    summarise([r for r in records if r["type"] in wanted and r["k"] < args.n], args.types)


if __name__ == "__main__":
    main()
