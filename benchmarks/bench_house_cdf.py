"""House CDFs with their own objects, relations and task: relations met and oracle success over seeds.

    python benchmarks/bench_house_cdf.py                     # every example in cdf/examples/houses, 20 seeds
    python benchmarks/bench_house_cdf.py --seeds 5 cdf/examples/houses/two_bedroom_flat.yaml

For each CDF and seed it generates the house (`cssg.generate_house`) and counts the CDF's relations (every
room's `relations`) that the generated house meets, as CSSG's own check reports them; then, when the CDF has a
task, it runs it as `luminous run` does (`cdf_episode.run_document`, the oracle planning; no frames) and counts
the successes. Every draw counts: a seed whose house cannot be generated counts all its relations unmet and
its task failed, and is listed; no draw is redrawn or dropped. CPU time is per seed (the machine is shared).
"""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.machine import machine
from luminous_sim import cdf
from luminous_sim.cdf import ChallengeDefinition
from luminous_sim.cdf_episode import run_document
from luminous_sim.cssg import generate_house
from luminous_sim.errors import LuminousError

EXAMPLES = Path(__file__).resolve().parents[1] / "cdf" / "examples" / "houses"


def relations_of(doc: ChallengeDefinition) -> int:
    """The CDF's relations, over every room."""
    house = doc.scene.house
    return sum(len(r.relations) for r in house.rooms) if house is not None else 0


@dataclass
class Figures:
    """One CDF's counts over its seeds."""

    cdf: str
    seeds: int
    relations: int
    task: bool
    met: int = 0
    solved: int = 0
    failed: list[str] = field(default_factory=list)
    cpu: list[float] = field(default_factory=list)


def measure(path: Path, seeds: int) -> Figures:
    """Relations met and oracle success over `seeds` seeds of one house CDF (every draw counted)."""
    doc = cdf.load(path)
    wanted = relations_of(doc)
    met = solved = 0
    failed: list[str] = []
    cpu: list[float] = []
    for seed in range(seeds):
        start = time.process_time()
        try:
            report = generate_house(doc, seed=seed).report
            met += sum(c.met for r in report.rooms.values() for c in r.relations if c.explicit)
        except LuminousError as exc:
            failed.append(f"seed {seed}: generation: {str(exc)[:160]}")
            cpu.append(time.process_time() - start)
            continue
        if doc.task is not None:
            try:
                result = run_document(doc, str(path), seed=seed, record_frames=False).result
                solved += result.success
                if not result.success:
                    failed.append(f"seed {seed}: oracle: {result.failure[:160]}")
            except LuminousError as exc:
                failed.append(f"seed {seed}: run: {str(exc)[:160]}")
        cpu.append(time.process_time() - start)
    return Figures(path.name, seeds, wanted * seeds, doc.task is not None, met, solved, failed, cpu)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cdfs", nargs="*", type=Path, help="house CDFs (default: every example)")
    parser.add_argument("--seeds", type=int, default=20)
    args = parser.parse_args(argv)
    paths = args.cdfs or sorted(EXAMPLES.glob("*.yaml"))
    print(f"machine: {machine()}")
    for path in paths:
        m = measure(path, args.seeds)
        cpu = sorted(m.cpu)
        rel = (f"relations met {m.met}/{m.relations} ({100 * m.met / m.relations:.1f}%)" if m.relations
               else "no relations")
        task = f"oracle success {m.solved}/{m.seeds}" if m.task else "no task"
        print(f"{m.cdf}: {m.seeds} seeds: {rel}; {task}; CPU s per seed median "
              f"{cpu[len(cpu) // 2]:.1f} (range {cpu[0]:.1f}-{cpu[-1]:.1f})")
        for line in m.failed:
            print(f"  {line}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
