"""Oracle figures in the layout of the paper's Table 2: success per task type over sampled tasks in
generated scenes, subgoal success per subgoal type, median planning time, and low-level trajectory
length per type next to ALFRED's (spec 2.3, train means).

    python benchmarks/bench_oracle.py --n 50      # the issue's figure (slow: about 10 s per episode)
    python benchmarks/bench_oracle.py --n 5
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections import Counter
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


def main() -> None:
    from luminous_sim.cssg.baseline import empty_cdf
    from luminous_sim.cssg.generate import generate
    from luminous_sim.episode import run_episode
    from luminous_sim.errors import LuminousError

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=5, help="tasks per type")
    ap.add_argument("--types", nargs="*", default=list(ALFRED_MEAN_LENGTH))
    args = ap.parse_args()
    subgoal_ok, subgoal_all = Counter(), Counter()
    rows = []
    for task_type in args.types:
        ok = gc_done = gc_total = 0
        lengths, plan_times, wall = [], [], []
        skipped = 0
        for k in range(args.n):
            room = ROOMS[task_type][k % len(ROOMS[task_type])]
            scene = generate(empty_cdf(room), seed=1000 + k).scene
            t0 = time.perf_counter()
            try:
                r, traj = run_episode(scene, task_type, seed=k, record_frames=False, return_trajectory=True)
            except LuminousError:
                skipped += 1  # no feasible task of this type in this scene
                continue
            wall.append(time.perf_counter() - t0)
            ok += r.success
            gc_done += r.goal_conditions[0]
            gc_total += r.goal_conditions[1]
            lengths.append(r.low_actions)
            plan_times.append(r.planning_seconds)
            for h in traj.high_pddl:
                a = h["planner_action"]["action"]
                if a != "End":
                    subgoal_all[a] += 1
                    subgoal_ok[a] += 1
            for a in traj.failed_subgoals:
                subgoal_all[a] += 1
        n = len(lengths)
        rows.append((task_type, ok, n, gc_done, gc_total, skipped,
                     statistics.median(plan_times) if plan_times else float("nan"),
                     statistics.mean(lengths) if lengths else float("nan"),
                     statistics.median(wall) if wall else float("nan")))
    print(f"{'task type':36}{'success':>16}{'goal-cond.':>12}{'no task':>9}{'plan (med)':>12}"
          f"{'low actions':>13}{'ALFRED':>8}{'episode':>10}")
    for t, ok, n, d, tot, sk, pt, ln, w in rows:
        sr = f"{ok}/{n} ({100 * ok / n:.0f}%)" if n else "n/a"
        gc = f"{100 * d / tot:.0f}%" if tot else "n/a"
        print(f"{t:36}{sr:>16}{gc:>12}{sk:>9}{1000 * pt:>10.0f}ms{ln:>13.1f}{ALFRED_MEAN_LENGTH[t]:>8.1f}{w:>9.1f}s")
    print("\nsubgoal success (executed without failure / attempted):")
    for a in sorted(subgoal_all):
        print(f"  {a:16} {subgoal_ok[a]}/{subgoal_all[a]} ({100 * subgoal_ok[a] / subgoal_all[a]:.0f}%)")


if __name__ == "__main__":
    main()
