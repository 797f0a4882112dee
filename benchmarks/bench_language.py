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

With `--speaker PATH` (a checkpoint of `luminous speaker train --data <the --alfred folder>`), BLEU-4 against
ALFRED's human annotations of the trajectories the checkpoint held out: goal directives of ALFRED's own
templates (lower-cased type names), of the project's templates and of the speaker; step instructions of the
speaker (on ALFRED's trajectories) and of the templates (on a method-(b) build of the held-out designs, scored
where the build's subgoals are ALFRED's, one for one).

    python benchmarks/bench_language.py [--split U+] [--count 7] [--alfred ../shared/alfred/valid_seen]
        [--alfred-count 40] [--build DIR] [--examples 3] [--speaker speaker.pt]
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


def speaker_bleu(checkpoint: Path, split_dir: Path, beam: int) -> None:
    """BLEU-4 of templates and speaker against the human annotations of the checkpoint's held-out trajectories."""
    from luminous_sim.data import BuildOptions, build_from_alfred
    from luminous_sim.language.speaker import Speaker, corpus_bleu, load_trajectories, tokenize
    from luminous_sim.language.speaker.checkpoint import load_checkpoint
    from luminous_sim.language.speaker.evaluate import evaluate
    from luminous_sim.tasks import PddlParams, TaskInstance, goal_for, task_description
    from luminous_sim.tasks.templates import alfred_description

    keys = set(load_checkpoint(checkpoint).get("held_out_keys", []))
    held = [t for t in load_trajectories(split_dir) if t.key in keys]
    if not held:
        print(f"(none of {checkpoint}'s held-out trajectories are under {split_dir})")
        return
    speaker = Speaker.load(checkpoint, beam_width=beam)
    ev = evaluate(speaker, held, beam_width=beam)
    goals: dict[str, list[list[str]]] = {"ALFRED's templates": [], "templates": []}
    refs = []
    for i, traj in enumerate(held):
        data = json.loads(traj.path.read_text())
        params = PddlParams.from_json(data["pddl_params"])
        task = TaskInstance(data["task_type"], params, goal_for(params, data["task_type"]), 0)
        rng = np.random.default_rng(i)
        goals["ALFRED's templates"].append(tokenize(alfred_description(task, rng)))
        goals["templates"].append(tokenize(task_description(task, np.random.default_rng(i))))
        refs.append([tokenize(a.task_desc) for a in traj.annotations])
    print(f"BLEU-4 against ALFRED's human annotations, {len(held)} trajectories {checkpoint} held out of {split_dir}:")
    for name, hyps in goals.items():
        print(f"  goal directives, {name:22s} {corpus_bleu(hyps, refs):.4f}")
    print(f"  goal directives, {'speaker (beam ' + str(beam) + ')':22s} {ev.bleu_goals:.4f}")
    print(f"  step instructions, speaker           {ev.bleu_steps:.4f}  ({ev.n_steps} subgoals)")
    with tempfile.TemporaryDirectory(prefix="bench_language_bleu_") as tmp:
        designs = Path(tmp) / split_dir.name
        for traj in held:  # the held-out designs alone, as a split folder
            (designs / traj.path.parent.parent.name).mkdir(parents=True, exist_ok=True)
            (designs / traj.path.parent.parent.name / traj.path.parent.name).symlink_to(traj.path.parent)
        build_from_alfred(Path(tmp) / "build", designs, None, None, BuildOptions(frames=False, video=False),
                          progress=False)
        ours = {p.parent.name: json.loads(p.read_text()) for p in (Path(tmp) / "build").rglob("traj_data.json")}
    hyps_t, hyps_s, step_refs = [], [], []
    matched = 0
    for traj in held:
        built = ours.get(traj.path.parent.name)
        if built is None:
            continue
        actions = [h["planner_action"]["action"] for h in built["plan"]["high_pddl"]][:-1]
        if actions != [sg.action for sg in traj.subgoals]:
            continue
        matched += 1
        said = built["turk_annotations"]["anns"][0]["high_descs"]
        for i, (sg, seg) in enumerate(zip(traj.subgoals, traj.segments, strict=True)):
            hyps_t.append(tokenize(said[i]))
            hyps_s.append(tokenize(speaker.describe(sg, seg)))
            step_refs.append([tokenize(a.high_descs[i]) for a in traj.annotations])
    print(f"  step instructions on the {matched} of {len(held)} designs whose built subgoals are ALFRED's "
          f"({len(step_refs)} subgoals): templates {corpus_bleu(hyps_t, step_refs):.4f}, "
          f"speaker {corpus_bleu(hyps_s, step_refs):.4f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--split", default="U+")
    ap.add_argument("--count", type=int, default=7, help="episodes of the split to build (0: none)")
    ap.add_argument("--alfred", type=Path, default=DEFAULT_ALFRED, help="an ALFRED split folder")
    ap.add_argument("--alfred-count", type=int, default=0, help="build the first N ALFRED designs (method (b))")
    ap.add_argument("--build", type=Path, action="append", default=[], help="an existing build folder to read")
    ap.add_argument("--examples", type=int, default=3, help="example sentences shown per problem")
    ap.add_argument("--speaker", type=Path, default=None, help="a speaker checkpoint trained on --alfred")
    ap.add_argument("--beam", type=int, default=3, help="the speaker's beam width (default 3)")
    args = ap.parse_args()
    if args.speaker is not None:
        speaker_bleu(args.speaker, args.alfred.resolve(), args.beam)
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
