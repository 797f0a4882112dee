"""The native text env (`Luminous-Text-v0`): steps per second in one process, reset time, and text/embodied
agreement (the text expert's commands, carried out in a `World` of the same entry, solve it there).

    python benchmarks/bench_text.py speed [--entries 8] [--steps 400] [--repeats 5] [--alfworld-games GAMES]
    python benchmarks/bench_text.py agree --split U+ [--start 0] [--count N] [--json OUT.json]

`speed` plays random admissible commands (seeded) in the first `--entries` entries of U+ (the same entries
and commands in every repeat), and gives the median and spread of the repeats; with `--alfworld-games` it
plays random admissible commands the same way in ALFWorld's own `AlfredTWEnv`-wrapped TextWorld games
(`benchmarks/bench_alfworld.py` makes them) for the like-with-like ratio. `agree` counts, per task type,
the entries the text expert wins, and those whose commands carried out solve the embodied entry, with every
disagreement named by its cause. Figures: docs/benchmarks.md ("The native text env")."""

from __future__ import annotations

import argparse
import json
import random
import statistics
import sys
import time
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from machine import machine


def play_random(env: Any, rng: random.Random, steps: int) -> int:
    """Random admissible commands until `steps` have been taken (resetting the same entry when one ends)."""
    done = 0
    admissible = env.game.admissible()
    while done < steps:
        _, _, terminated, truncated, info = env.step(rng.choice(admissible))
        admissible, done = info["admissible_commands"], done + 1
        if terminated or truncated:
            return done
    return done


def speed(entries: int, steps: int, repeats: int) -> dict[str, Any]:
    from luminous_sim.env.text_env import TextEnv

    env = TextEnv(split="U+", max_steps=10_000)
    first, again, rates = [], [], []
    for i in range(entries):  # the first reset of an entry makes its scene; the next ones do not need to
        t = time.perf_counter()
        env.reset(options={"split": "U+", "index": i})
        first.append(time.perf_counter() - t)
    for _ in range(repeats):
        rng, taken, seconds = random.Random(0), 0, 0.0
        for i in range(entries):
            t = time.perf_counter()
            env.reset(options={"split": "U+", "index": i})
            again.append(time.perf_counter() - t)
            t = time.perf_counter()
            taken += play_random(env, rng, steps)
            seconds += time.perf_counter() - t
        rates.append(taken / seconds)
    return {"steps_per_second": _spread(rates), "first_reset_s": _spread(first), "reset_s": _spread(again),
            "entries": entries, "steps_per_entry": steps, "repeats": repeats}


def alfworld_speed(games: Path, steps: int, repeats: int, entries: int) -> dict[str, Any]:
    import textworld
    from alfworld.agents.environment.alfred_tw_env import AlfredDemangler, AlfredInfos
    from textworld.envs import PddlEnv

    files = sorted(games.rglob("game.tw-pddl"))[:entries]
    rates = []
    for _ in range(repeats):
        rng, taken, seconds = random.Random(0), 0, 0.0
        for f in files:
            env = AlfredInfos(AlfredDemangler(PddlEnv(textworld.EnvInfos(admissible_commands=True, won=True)),
                                              shuffle=False))
            env.load(str(f))
            state = env.reset()
            t = time.perf_counter()
            for _ in range(steps):
                state, _, done = env.step(rng.choice(state["admissible_commands"]))
                taken += 1
                if done:
                    break
            seconds += time.perf_counter() - t
        rates.append(taken / seconds)
    return {"steps_per_second": _spread(rates), "games": len(files), "steps_per_game": steps, "repeats": repeats}


def agree(split: str, start: int, count: int | None) -> dict[str, Any]:
    from luminous_sim.benchmark import benchmark_size
    from luminous_sim.env.text_env import TextEnv
    from luminous_sim.episodes import prepare
    from luminous_sim.errors import PlanningError
    from luminous_sim.tasks import goal_conditions
    from luminous_sim.text import TextExpert, carry_out
    from luminous_sim.world import World

    env = TextEnv(split=split)
    end = benchmark_size(split) if count is None else min(benchmark_size(split), start + count)
    rows: dict[str, Counter] = defaultdict(Counter)
    causes: dict[str, Counter] = defaultdict(Counter)
    t = time.perf_counter()
    for i in range(start, end):
        _, info = env.reset(options={"split": split, "index": i})
        task_type = info["task_type"]
        rows[task_type]["entries"] += 1
        try:
            expert = TextExpert(env.game, env.episode.task.goal, dict(env.episode.task.names))
        except PlanningError as exc:  # counted, with its cause
            causes[task_type][f"no text plan: {str(exc)[:60]}"] += 1
            continue
        while (command := expert.next_command()) is not None:
            _, _, terminated, truncated, info = env.step(command)
            if terminated or truncated:
                break
        if not info["won"]:
            causes[task_type]["text expert did not win"] += 1
            continue
        rows[task_type]["text_won"] += 1
        world = prepare(World(env.episode.scene), env.episode)
        try:
            got = carry_out(world, env.game.history, env.game.free)
            view = world.view()
            done, total = goal_conditions(env.episode.task, view.state, set(view.visible_objects()))
        finally:
            world.close()
        if got.ok and done == total:
            rows[task_type]["agree"] += 1
        else:
            cause = got.cause if not got.ok else f"goal not met in the world ({done}/{total})"
            causes[task_type][_cause_kind(cause)] += 1
    return {"split": split, "start": start, "end": end, "seconds": round(time.perf_counter() - t, 1),
            "types": {k: dict(v) for k, v in sorted(rows.items())},
            "causes": {k: dict(v) for k, v in sorted(causes.items())}}


def _cause_kind(cause: str) -> str:
    """A disagreement's cause without the object ids (so that like causes count together)."""
    for kind in ("no pose from which", "is not on or in", "is not where the agent stands", "goal not met",
                 "no spot", "is full"):
        if kind in cause:
            return kind
    return cause[:80]


def _spread(values: list[float]) -> dict[str, float]:
    return {"median": round(statistics.median(values), 4), "min": round(min(values), 4),
            "max": round(max(values), 4), "n": len(values)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="what", required=True)
    s = sub.add_parser("speed")
    s.add_argument("--entries", type=int, default=8)
    s.add_argument("--steps", type=int, default=400)
    s.add_argument("--repeats", type=int, default=5)
    s.add_argument("--alfworld-games", type=Path, default=None)
    a = sub.add_parser("agree")
    a.add_argument("--split", default="U+")
    a.add_argument("--start", type=int, default=0)
    a.add_argument("--count", type=int, default=None)
    for p in (s, a):
        p.add_argument("--json", type=Path, default=None)
    args = parser.parse_args(argv)
    out: dict[str, Any] = {"machine": machine()}
    if args.what == "speed":
        out["luminous"] = speed(args.entries, args.steps, args.repeats)
        if args.alfworld_games is not None:
            out["alfworld"] = alfworld_speed(args.alfworld_games, args.steps, args.repeats, args.entries)
            out["ratio"] = round(out["luminous"]["steps_per_second"]["median"]
                                 / out["alfworld"]["steps_per_second"]["median"], 1)
    else:
        out["agree"] = agree(args.split, args.start, args.count)
    print(json.dumps(out, indent=1, sort_keys=True))
    if args.json is not None:
        args.json.write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
