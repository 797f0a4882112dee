"""Symbolic planner figures: per ALFRED task type, success rate, median/max planning time, plan length
and nodes expanded, over randomized hand-built kitchens and bedrooms.

    python benchmarks/bench_planner.py                      # built-in A*, 20 states per task type
    python benchmarks/bench_planner.py --trials 5 --backends astar,fd,up   # also Fast Downward
    python benchmarks/bench_planner.py --optimal-gap    # A* cost minus the optimal cost (FD, A* h_max)

Each state re-draws the tests' kitchen/bedroom: 1-3 extra instances of each pickupable type, every
pickupable object on or in a random fixed receptacle that can hold it, doors open with probability
0.3, dishes dirty. Task parameters are drawn from each type's options that are feasible in it;
half the goals carry ALFRED's "every receptacle closed" conjunct. Every plan is replayed through
the state rules and checked with the task layer's goal evaluator.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic import external, replay, solve
from luminous_sim.states import ObjectState, WorldState
from luminous_sim.states.tables import GATING_OPENABLE
from luminous_sim.tasks.evaluate import goal_satisfied
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import goal_for
from luminous_sim.vocab import abilities, can_contain
from tests.planning.scenes import BEDROOM, KITCHEN, KITCHEN_DIRTY, KITCHEN_FAUCETS

TASKS: dict[str, tuple[str, list[PddlParams]]] = {
    "pick_and_place_simple": (
        "kitchen",
        [
            PddlParams("Potato", "Fridge"),
            PddlParams("Mug", "Cabinet"),
            PddlParams("Tomato", "CounterTop", object_sliced=True),
        ],
    ),
    "pick_two_obj_and_place": (
        "kitchen",
        [
            PddlParams("Apple", "GarbageCan"),
            PddlParams("Egg", "DiningTable"),
            PddlParams("Bread", "Fridge", object_sliced=True),
        ],
    ),
    "look_at_obj_in_light": (
        "bedroom",
        [PddlParams("Book", toggle_target="DeskLamp"), PddlParams("CD", toggle_target="DeskLamp")],
    ),
    "pick_clean_then_place_in_recep": (
        "kitchen",
        [
            PddlParams("Mug", "CoffeeMachine"),
            PddlParams("Plate", "Cabinet"),
            PddlParams("Lettuce", "Fridge", object_sliced=True),
        ],
    ),
    "pick_heat_then_place_in_recep": (
        "kitchen",
        [
            PddlParams("Potato", "CounterTop"),
            PddlParams("Egg", "GarbageCan"),
            PddlParams("Apple", "DiningTable", object_sliced=True),
        ],
    ),
    "pick_cool_then_place_in_recep": (
        "kitchen",
        [
            PddlParams("Tomato", "DiningTable"),
            PddlParams("Pan", "StoveBurner"),
            PddlParams("Potato", "CounterTop", object_sliced=True),
        ],
    ),
    "pick_and_place_with_movable_recep": (
        "kitchen",
        [
            PddlParams("Apple", "DiningTable", mrecep_target="Plate"),
            PddlParams("Fork", "CounterTop", mrecep_target="Mug"),
            PddlParams("Tomato", "DiningTable", mrecep_target="Bowl", object_sliced=True),
        ],
    ),
}


def random_state(room: str, rng: np.random.Generator) -> WorldState:
    """A re-drawn kitchen or bedroom (see the module docstring)."""
    layout = dict(KITCHEN if room == "kitchen" else BEDROOM)
    fixed = [k for k, (t, _) in layout.items() if not abilities(t).pickupable]
    for k, (t, _) in list(layout.items()):
        if abilities(t).pickupable and t not in ("Box",):
            for i in range(int(rng.integers(0, 3))):
                layout[f"{t}|x{k.split('|')[1]}{i}"] = (t, None)
    objs = []
    for k, (t, parent) in layout.items():
        fields: dict = {}
        if (
            (abilities(t).pickupable
            and parent is None)
            or (abilities(t).pickupable and rng.random() < 0.7)
        ):
            spots = [r for r in fixed if can_contain(layout[r][0], t)]
            parent = spots[int(rng.integers(len(spots)))] if spots else parent
        fields["parent"] = parent
        if t in GATING_OPENABLE and rng.random() < 0.3:
            fields["isOpen"] = True
        if room == "kitchen" and t in {KITCHEN[d][0] for d in KITCHEN_DIRTY}:
            fields["isDirty"] = True
        objs.append(ObjectState(k, t, **fields))
    faucets = KITCHEN_FAUCETS if room == "kitchen" else {}
    return WorldState.of(objs, faucet_basin=faucets)


def run(backend: str, trials: int, seed: int, timeout: float, optimal_gap: bool = False) -> None:
    rng = np.random.default_rng(seed)
    print(f"\nbackend {backend}: {trials} states per task type")
    print(
        f"{'task type':36s} {'ok':>5s} {'t med ms':>9s} {'t max ms':>9s} {'len med':>8s} {'len max':>8s} "
        f"{'cost med':>8s} {'expanded med':>12s}"
    )
    all_times = []
    for task, (room, options) in TASKS.items():
        times, lengths, costs, expanded, gaps, ok = [], [], [], [], [], 0
        for _ in range(trials):
            params = options[int(rng.integers(len(options)))]
            state = random_state(room, rng)
            while task == "pick_two_obj_and_place" and len(state.of_type(params.object_target)) < 2:
                state = random_state(room, rng)
            goal = goal_for(params, task, closed_receptacles=bool(rng.integers(2)))
            try:
                plan = solve(state, goal, backend=backend, timeout=timeout)
            except PlanningError as exc:
                print(f"  {task} {params.to_json()}: {exc}")
                continue
            final = replay(state, plan.actions)
            if not goal_satisfied(goal, final):
                print(f"  {task}: plan does not reach the goal: {plan.summary()}")
                continue
            ok += 1
            times.append(plan.seconds * 1000)
            lengths.append(len(plan.actions))
            costs.append(plan.cost)
            expanded.append(plan.expanded)
            if optimal_gap:
                external.FD_CONFIG = "optimal"
                try:
                    gaps.append(plan.cost - solve(state, goal, backend="fd", timeout=timeout).cost)
                except PlanningError as exc:
                    print(f"  optimal plan not found: {exc}")
                finally:
                    external.FD_CONFIG = "lama-first"
        all_times += times
        if not times:
            print(f"{task:36s} {ok:>2d}/{trials:<2d}")
            continue
        print(
            f"{task:36s} {ok:>2d}/{trials:<2d} {statistics.median(times):9.1f} {max(times):9.1f} "
            f"{statistics.median(lengths):8.1f} {max(lengths):8d} {statistics.median(costs):8.1f} "
            f"{statistics.median(expanded):12.1f}"
            + (
                f"   gap to optimal: max {max(gaps):.0f}, {sum(g == 0 for g in gaps)}/{len(gaps)} optimal"
                if gaps
                else ""
            )
        )
    if all_times:
        print(f"{'all':36s} {'':5s} {statistics.median(all_times):9.1f} {max(all_times):9.1f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=20, help="states per task type")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--backends", default="astar", help="comma-separated: astar, fd, up")
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument(
        "--optimal-gap",
        action="store_true",
        help="compare costs with Fast Downward's optimal plans",
    )
    args = ap.parse_args()
    t0 = time.perf_counter()
    for backend in args.backends.split(","):
        run(backend.strip(), args.trials, args.seed, args.timeout, args.optimal_gap)
    print(f"\ntotal {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
