"""Oracle figures in the layout of the paper's Table 2: success per task type over sampled tasks in
generated scenes, subgoal success per subgoal type, median planning time, and low-level trajectory
length per type next to ALFRED's (spec 2.3, train means).

    python benchmarks/bench_oracle.py --n 50 --jobs 2   # the issue's figure (about 5 s per episode)
    python benchmarks/bench_oracle.py --n 5

Rooms are default rooms of a room type the task type allows; where none of three holds a task of the
type that fits physically (two of a kind for pick_two, room in the receptacle), a room is generated for a
drawn task ('for task' column). 'no task' counts slots where no such room was found.
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


def episode(task_type: str, k: int) -> dict:
    """Run task slot `k` of `task_type` in a generated room that supports such a task."""
    from luminous_sim.data import scene_for_task
    from luminous_sim.episode import run_episode
    from luminous_sim.errors import LuminousError

    room = ROOMS[task_type][k % len(ROOMS[task_type])]
    seed = 1000 + k
    try:
        scene = scene_for_task(task_type, room, seed)
        t0 = time.perf_counter()
        r, traj = run_episode(scene, task_type, seed=k, record_frames=False, return_trajectory=True)
    except LuminousError as exc:  # no room of this type supports the task, or none fits physically
        return {"type": task_type, "k": k, "room": room, "scene_seed": seed, "success": None, "no_task": 1,
                "why": str(exc)}
    ok_subgoals = [h["planner_action"]["action"] for h in traj.high_pddl if h["planner_action"]["action"] != "End"]
    return {"type": task_type, "k": k, "room": room, "scene_seed": seed, "task_driven": bool(scene.source),
            "goal": r.goal, "success": r.success,
            "goal_conditions": list(r.goal_conditions), "low_actions": r.low_actions,
            "planning_seconds": r.planning_seconds, "episode_seconds": time.perf_counter() - t0,
            "subgoals_ok": ok_subgoals, "subgoals_failed": traj.failed_subgoals, "failures": traj.failures,
            "replans": traj.replans, "no_task": 0}


def _median(records: list[dict], key: str) -> float:
    return statistics.median(r[key] for r in records) if records else float("nan")


def summarise(records: list[dict], types: list[str]) -> None:
    by_type = defaultdict(list)
    for r in records:
        by_type[r["type"]].append(r)
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
