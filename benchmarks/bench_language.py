"""Instruction quality of builds, by checks that do not use the language layer's name table
(`luminous_sim.language.lint`): goal directives and step instructions with an ALFRED type name glued into
one word ("stoveburner", "dishsponge") or left in CamelCase, step instructions whose landmark is the target
itself ("to the sink near the sink"), and the distinct-sentence rate across a trajectory's three annotations
(distinct sentences at each position over all sentences; 1/3 means the three annotations are the same).

Sources:
  * a method-(a) build of episodes 0..COUNT-1 of a split (U+ by default), built here without frames;
  * ALFRED designs: the goal directives of every design of an ALFRED split folder (`--alfred`, e.g. your copy of
    valid_seen; three per design, as a build writes), which needs no simulation, and, with `--alfred-count N`,
    a method-(b) build of its first N designs (goal directives and step instructions);
  * `--build DIR` (repeatable): existing build folders, read as they are (e.g. one built by an older version).

    python benchmarks/bench_language.py [--split U+] [--count 7] [--alfred ../shared/alfred/valid_seen]
        [--alfred-count 40] [--build DIR] [--examples 3]
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path

import numpy as np

from luminous_sim.language.lint import count_problems, distinct_rate, glued_names, self_landmarks

ANNOTATIONS = 3
DEFAULT_ALFRED = Path(__file__).resolve().parents[1] / ".." / "shared" / "alfred" / "valid_seen"


def _annotations(root: Path) -> list[list[dict]]:
    """Each trial's annotations (task_desc, high_descs) under a build folder."""
    out = []
    for path in sorted(root.rglob("traj_data.json")):
        anns = json.loads(path.read_text()).get("turk_annotations", {}).get("anns", [])
        if anns:
            out.append(anns)
    return out


def _report(name: str, trials: list[list[dict]], examples: int) -> None:
    goals = [a["task_desc"] for anns in trials for a in anns]
    steps = [h for anns in trials for a in anns for h in a["high_descs"]]
    g, s = count_problems(goals), count_problems(steps)
    gd = [distinct_rate([[a["task_desc"]] for a in anns]) for anns in trials]
    sd = [distinct_rate([a["high_descs"] for a in anns]) for anns in trials]
    print(f"{name}: {len(trials)} trials")
    print(f"  goal directives    {g['texts']:6d}  glued names {g['glued']:5d}  "
          f"self-landmarks {g['self_landmarks']:4d}  distinct across annotations {_rate(gd)}")
    print(f"  step instructions  {s['texts']:6d}  glued names {s['glued']:5d}  "
          f"self-landmarks {s['self_landmarks']:4d}  distinct across annotations {_rate(sd)}")
    _examples("glued", [t for t in goals + steps if glued_names(t)], examples)
    _examples("self-landmark", [t for t in steps if self_landmarks(t)], examples)
    _examples("goal", goals[::ANNOTATIONS], examples)


def _rate(pairs: Iterable[tuple[int, int]]) -> str:
    pairs = list(pairs)
    distinct, total = sum(p[0] for p in pairs), sum(p[1] for p in pairs)
    return f"{distinct / total:.3f} ({distinct}/{total})" if total else "-"


def _examples(what: str, texts: list[str], n: int) -> None:
    for t in list(dict.fromkeys(texts))[:n]:
        print(f"    e.g. {what}: {t!r}")


def alfred_goals(split_dir: Path, examples: int) -> None:
    """Goal directives for every design of an ALFRED split folder, three per design (no simulation)."""
    from luminous_sim.tasks import PddlParams, TaskInstance, goal_for, task_description

    trials = []
    for i, path in enumerate(sorted(split_dir.glob("*/*/traj_data.json"))):
        data = json.loads(path.read_text())
        params = PddlParams.from_json(data["pddl_params"])
        task = TaskInstance(data["task_type"], params, goal_for(params, data["task_type"]), 0)
        rngs = [np.random.default_rng(np.random.SeedSequence([i, k])) for k in range(ANNOTATIONS)]
        trials.append([{"task_desc": task_description(task, r), "high_descs": []} for r in rngs])
    goals = [a["task_desc"] for anns in trials for a in anns]
    g = count_problems(goals)
    print(f"ALFRED designs of {split_dir} (goal directives only, no simulation): {len(trials)} designs")
    print(f"  goal directives    {g['texts']:6d}  glued names {g['glued']:5d}  "
          f"distinct across annotations {_rate(distinct_rate([[a['task_desc']] for a in anns]) for anns in trials)}")
    _examples("glued", [t for t in goals if glued_names(t)], examples)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--split", default="U+")
    ap.add_argument("--count", type=int, default=7, help="episodes of the split to build (0: none)")
    ap.add_argument("--alfred", type=Path, default=DEFAULT_ALFRED, help="an ALFRED split folder")
    ap.add_argument("--alfred-count", type=int, default=0, help="build the first N ALFRED designs (method (b))")
    ap.add_argument("--build", type=Path, action="append", default=[], help="an existing build folder to read")
    ap.add_argument("--examples", type=int, default=3, help="example sentences shown per problem")
    args = ap.parse_args()
    for folder in args.build:
        _report(f"build {folder}", _annotations(folder), args.examples)
    with tempfile.TemporaryDirectory(prefix="bench_language_") as tmp:
        if args.count:
            from luminous_sim.data import BuildOptions, build_split

            start = time.perf_counter()
            report = build_split(Path(tmp) / "split", args.split, args.count, None,
                                 BuildOptions(frames=False, video=False), progress=False)
            print(f"[{args.split} build of {args.count} episodes: {report.built} built, {report.failed} failed, "
                  f"{time.perf_counter() - start:.0f} s]")
            _report(f"{args.split} episodes 0..{args.count - 1}", _annotations(Path(tmp) / "split"), args.examples)
        if args.alfred.is_dir():
            alfred_goals(args.alfred, args.examples)
            if args.alfred_count:
                from luminous_sim.data import BuildOptions, build_from_alfred

                start = time.perf_counter()
                report = build_from_alfred(Path(tmp) / "alfred", args.alfred, args.alfred_count, None,
                                           BuildOptions(frames=False, video=False), progress=False)
                print(f"[method (b) build of {args.alfred_count} designs: {report.built} built, {report.failed} "
                      f"failed, {time.perf_counter() - start:.0f} s]")
                _report(f"ALFRED designs, first {args.alfred_count}, built", _annotations(Path(tmp) / "alfred"),
                        args.examples)
        else:
            print(f"(no ALFRED split folder at {args.alfred}; pass --alfred DIR)")


if __name__ == "__main__":
    main()
