"""The instruction parser's accuracy (issue 43's targets: task type >= 0.97, all five slots exact >= 0.85 on
ALFRED's valid_seen human directives), on:

- every human annotation under `--alfred` (valid_seen: 820), from the directive alone and with its step
  instructions;
- the held-apart share of ALFRED's train designs the checkpoint recorded while training (the figures the
  epochs were chosen on; valid_seen is only reported);
- the template directives of the first `--entries` entries of each `--split` (each entry's own task
  instruction, made by `episodes.entry_spec`; 0 skips them, `all` takes every entry).

It prints one block per set: the share right of the task type, each slot, all five slots (`slots`) and
everything (`all`), and the time to parse them.

    python benchmarks/bench_parser.py --alfred ../shared/alfred/valid_seen --split U+ S+ --entries all
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from luminous_sim.agents import Annotated, InstructionParser, accuracy, default_parser, read_annotations


def split_annotations(split: str, count: int | None) -> list[Annotated]:
    """The template directive of each of a split's first `count` entries (None: every one), labelled by the
    entry's task."""
    from luminous_sim.benchmark import benchmark_entries
    from luminous_sim.episodes import entry_spec

    out = []
    for entry in benchmark_entries(split)[:count]:
        task = entry_spec(entry).task
        out.append(Annotated(task.instruction, (), entry.task_type, dict(entry.pddl_params),
                             f"{split}/{entry.index}"))
    return out


def report(name: str, parser: InstructionParser, examples: list[Annotated], with_steps: bool) -> None:
    start = time.perf_counter()
    scores = accuracy(parser, examples, with_steps)
    took = time.perf_counter() - start
    print(f"{name}: {len(examples)} annotations, parsed in {took:.2f} s")
    print("  " + json.dumps({k: round(v, 4) for k, v in scores.items()}))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--alfred", type=Path, default=Path("../shared/alfred/valid_seen"),
                        help="ALFRED annotations to score (default ../shared/alfred/valid_seen)")
    parser.add_argument("--parser", type=Path, default=None, help="a checkpoint (default: the shipped parser)")
    parser.add_argument("--split", nargs="*", default=["U+"], help="frozen splits whose template directives to score")
    parser.add_argument("--entries", default="0", help="the first N entries of each split ('all': every one; 0: none)")
    args = parser.parse_args()
    model = InstructionParser.load(args.parser) if args.parser else default_parser()
    examples = read_annotations(args.alfred)
    report(f"{args.alfred} (directive)", model, examples, False)
    report(f"{args.alfred} (directive + steps)", model, examples, True)
    last = model.record.get("epochs", [{}])[-1]
    for key in ("held_apart_directive", "held_apart_with_steps"):
        if key in last:
            print(f"training record, {key} ({model.record['held_apart_annotations']} annotations, epoch "
                  f"{last['epoch']}):\n  {json.dumps(last[key])}")
    count = None if args.entries == "all" else int(args.entries)
    for split in args.split if count != 0 else ():
        examples = split_annotations(split, count)
        report(f"{split}, {len(examples)} entries (template directive)", model, examples, False)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
