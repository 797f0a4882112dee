"""ALFWorld's own code on a Luminous build: its generator (`alfworld-generate`) turns each trial's
`initial_state.pddl` and `traj_data.json` into `game.tw-pddl` and decides with its hand-coded expert whether
the game is solvable; its `AlfredTWEnv` (with `dataset.data_path` at the games) loads every game of the six
task types it supports, and the hand-coded expert plays each one there; ALFWorld's planner expert (Fast
Downward) plays a sample. Wins per task type over every entry
of each split, the denominator taken from the build's manifest: an entry that failed to build, a trial
ALFWorld skips (sliced objects, movable-receptacle tasks) or a game its generator found unsolvable counts as
a loss, named by cause. Needs `pip install alfworld==0.4.2` (the test extra).

    python benchmarks/bench_alfworld.py --build BUILD [--games GAMES] [--splits S+ U+] [--planner-sample 20]
        [--json OUT.json]

Figures: docs/benchmarks.md ("ALFWorld's own code on our builds")."""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import time
from collections import Counter, defaultdict
from itertools import pairwise
from pathlib import Path
from typing import Any

ALFWORLD_TYPES = {1: "pick_and_place_simple", 2: "look_at_obj_in_light", 3: "pick_clean_then_place_in_recep",
                  4: "pick_heat_then_place_in_recep", 5: "pick_cool_then_place_in_recep",
                  6: "pick_two_obj_and_place"}
"""ALFWorld's task-type ids (`alfred_tw_env.TASK_TYPES`): every ALFRED type but movable-receptacle tasks."""
MAX_STEPS = 50
"""ALFWorld's step limit per episode (its base config's `max_nb_steps_per_episode`)."""


def generate(build: Path, games: Path, split: str, jobs: int = 1) -> float:
    """Run ALFWorld's generator over one split of the build (seconds taken), in `jobs` processes at once, each
    over its own contiguous range of the trials (the generator's `--start`/`--end`)."""
    from alfworld.info import ALFRED_PDDL_PATH, ALFRED_TWL2_PATH

    trials = sorted((build / split).glob("*/*/traj_data.json"))
    script = shutil.which("alfworld-generate") or str(Path(sys.executable).parent / "alfworld-generate")
    shutil.rmtree(games / split, ignore_errors=True)  # the generator keeps an existing game's verdict
    bounds = [len(trials) * i // max(jobs, 1) for i in range(max(jobs, 1) + 1)]
    start = time.perf_counter()
    running = [subprocess.Popen([sys.executable, script, "--data_path", str(build / split), "--save_path",
                                 str(games / split), "--domain", ALFRED_PDDL_PATH, "--grammar", ALFRED_TWL2_PATH,
                                 "--start", str(lo), "--end", str(hi)],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
               for lo, hi in pairwise(bounds) if hi > lo]
    failed = [p.args for p in running if p.wait() != 0]
    if failed:
        raise subprocess.CalledProcessError(1, failed[0])
    return time.perf_counter() - start


def play(games: Path, max_steps: int = MAX_STEPS) -> dict[str, dict[str, Any]]:
    """Every game `AlfredTWEnv` loads under `games`, played by ALFWorld's hand-coded expert in that env: trial
    folder (relative to `games`) -> {"won", "steps"}."""
    from alfworld.agents.environment.alfred_tw_env import AlfredTWEnv

    config = {"dataset": {"data_path": str(games), "num_train_games": -1},
              "env": {"task_types": list(ALFWORLD_TYPES), "goal_desc_human_anns_prob": 0.0,
                      "domain_randomization": False, "expert_type": "handcoded"},
              "general": {"training_method": "dagger"},
              "dagger": {"training": {"max_nb_steps_per_episode": max_steps}},
              "logic": {}}
    tw = AlfredTWEnv(config, train_eval="train")
    out: dict[str, dict[str, Any]] = {}
    if not tw.game_files:
        return out
    env = tw.init_env(batch_size=1)
    try:
        for _ in range(len(tw.game_files)):
            _, infos = env.reset()
            game = Path(infos["extra.gamefile"][0]).parent.relative_to(games).as_posix()
            won, steps = bool(infos["won"][0]), 0
            while not won and steps < max_steps:
                _, _, dones, infos = env.step([infos["extra.expert_plan"][0][0]])
                won, steps = bool(infos["won"][0]), steps + 1
                if dones[0]:
                    break
            out[game] = {"won": won, "steps": steps}
    finally:
        env.close()
    return out


def play_planner(games: Path, sample: int, max_steps: int = MAX_STEPS) -> dict[str, bool]:
    """The first `sample` solvable games under `games` (sorted) played by ALFWorld's planner expert (Fast
    Downward's plan, `AlfredExpert(expert_type="planner")`): trial folder -> won."""
    import textworld
    from alfworld.agents.environment.alfred_tw_env import AlfredDemangler, AlfredExpert, AlfredExpertType, AlfredInfos
    from textworld.envs import PddlEnv

    files = [f for f in sorted(games.rglob("game.tw-pddl")) if json.loads(f.read_text()).get("solvable")][:sample]
    out = {}
    for f in files:
        infos = textworld.EnvInfos(admissible_commands=True, won=True, policy_commands=True)
        env = AlfredExpert(AlfredInfos(AlfredDemangler(PddlEnv(infos), shuffle=False)),
                           expert_type=AlfredExpertType.PLANNER)
        env.load(str(f))
        state, steps = env.reset(), 0
        while not state["won"] and steps < max_steps and state["extra.expert_plan"]:
            state, _, _ = env.step(state["extra.expert_plan"][0])
            steps += 1
        out[f.parent.relative_to(games).as_posix()] = bool(state["won"])
    return out


def loss_cause(record: dict[str, Any], game_dir: Path, played: dict[str, dict[str, Any]]) -> str | None:
    """Why a manifest entry is not a win (None for a win)."""
    if record["status"] != "built":
        return f"not built ({record['stage']})"
    trial = record["trial"]
    if "movable" in trial or "Sliced" in trial:
        return "skipped by ALFWorld (sliced object)" if "Sliced" in trial else "skipped by ALFWorld (movable)"
    game = game_dir / record["split"] / trial / "game.tw-pddl"
    if not game.is_file():
        return "no game (no initial_state.pddl)"
    if not json.loads(game.read_text()).get("solvable"):
        return "unsolvable by ALFWorld's generator"
    got = played.get(f"{record['split']}/{trial}")
    if got is None:
        return "not loaded by AlfredTWEnv"
    return None if got["won"] else f"expert lost in AlfredTWEnv (step limit {MAX_STEPS})"


def measure(build: Path, games: Path, splits: list[str], planner_sample: int = 0, jobs: int = 1) -> dict[str, Any]:
    from luminous_sim.data import Manifest

    manifest = list(Manifest(build / "manifest.jsonl"))
    out: dict[str, Any] = {"splits": {}}
    for split in splits:
        seconds = generate(build, games, split, jobs)
        start = time.perf_counter()
        played = {f"{split}/{k}": v for k, v in play(games / split).items()}
        play_seconds = time.perf_counter() - start
        rows: dict[str, Counter] = defaultdict(Counter)
        causes: dict[str, Counter] = defaultdict(Counter)
        lost: list[dict[str, str]] = []
        for record in (r for r in manifest if r["split"] == split):
            task_type = record["task_type"]
            cause = loss_cause(record, games, played)
            rows[task_type]["entries"] += 1
            sliced = "Sliced" in (record.get("trial") or "")
            rows[task_type]["unsliced"] += not sliced
            rows[task_type]["won"] += cause is None
            if cause is not None:
                causes[task_type][cause] += 1
                if not cause.startswith("skipped by ALFWorld"):
                    lost.append({"trial": record.get("trial") or record["key"], "cause": cause})
        planner = play_planner(games / split, planner_sample) if planner_sample else {}
        steps = [v["steps"] for v in played.values() if v["won"]]
        out["splits"][split] = {"types": {t: dict(rows[t]) for t in sorted(rows)},
                                "causes": {t: dict(causes[t]) for t in sorted(causes)},
                                "lost": lost,
                                "generate_seconds": round(seconds, 1), "play_seconds": round(play_seconds, 1),
                                "games_played": len(played),
                                "planner_sample": {"games": len(planner), "won": sum(planner.values())},
                                "median_expert_steps": sorted(steps)[len(steps) // 2] if steps else None}
    return out


def table(result: dict[str, Any]) -> str:
    lines = []
    for split, got in result["splits"].items():
        lines.append(f"{split}: {got['games_played']} games played; generator {got['generate_seconds']} s, "
                     f"play {got['play_seconds']} s; ALFWorld's planner expert won {got['planner_sample']['won']} "
                     f"of a sample of {got['planner_sample']['games']}")
        lines.append(f"  {'task type':34s} {'entries':>7s} {'won':>5s} {'won/entries':>11s} {'won/unsliced':>12s}")
        total: Counter = Counter()
        for task_type, row in got["types"].items():
            if task_type not in ALFWORLD_TYPES.values():
                continue
            total.update(row)
            lines.append(f"  {task_type:34s} {row['entries']:7d} {row['won']:5d} {row['won'] / row['entries']:11.3f} "
                         f"{_share(row['won'], row['unsliced']):>12s}")
        if total["entries"]:
            lines.append(f"  {'six types':34s} {total['entries']:7d} {total['won']:5d} "
                         f"{total['won'] / total['entries']:11.3f} {_share(total['won'], total['unsliced']):>12s}")
        for task_type, causes in got["causes"].items():
            for cause, n in sorted(causes.items()):
                lines.append(f"    loss {task_type}: {cause}: {n}")
        for loss in got.get("lost", []):
            lines.append(f"    lost (not skipped): {loss['trial']}: {loss['cause']}")
    return "\n".join(lines)


def _share(won: int, of: int) -> str:
    return f"{won / of:.3f}" if of else "n/a (none)"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=Path, required=True, help="a `luminous dataset build` folder")
    parser.add_argument("--games", type=Path, default=None, help="where ALFWorld's games go (default BUILD-games)")
    parser.add_argument("--splits", nargs="+", default=None, help="splits of the build (default: all it holds)")
    parser.add_argument("--planner-sample", type=int, default=20,
                        help="games also played by ALFWorld's planner expert (Fast Downward), the first N (default 20)")
    parser.add_argument("--jobs", type=int, default=1,
                        help="generator processes at once, each over a range of the trials (default 1)")
    parser.add_argument("--json", type=Path, default=None, help="also write the figures here")
    args = parser.parse_args(argv)
    games = args.games or args.build.with_name(args.build.name + "-games")
    splits = args.splits or sorted(p.name for p in args.build.iterdir() if p.is_dir())
    result = measure(args.build, games, splits, args.planner_sample, args.jobs)
    print(table(result))
    if args.json is not None:
        args.json.write_text(json.dumps(result, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
