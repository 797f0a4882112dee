"""The frozen splits: each split's manifest, shipped in `luminous_sim/benchmark/data/<split>.jsonl` (a header
line, then one line per episode: task type, layout, draw and its seed, task parameters, start, `episode_key`),
read here. Entry `i` of a split is line `i + 1`, the same on every machine."""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from luminous_sim.benchmark.counts import Layout
from luminous_sim.splits import SplitError, plus_split
from luminous_sim.world import AgentPose

FROZEN_FORMAT = "luminous-frozen-split/1"
SPLIT_VERSION = 1
"""The version of the frozen splits; a generator change that changes their episodes makes a new one."""
DATA_DIR = Path(__file__).parent / "data"
FROZEN = ("S+", "U+")
"""The splits that are frozen (their manifests ship with the package). U+test (`PAPER_COUNTS` has its counts) is
not frozen yet: its entries are refused with a message saying so."""


CACHE_VAR = "LUMINOUS_CACHE"
"""The environment variable naming the cache folder (default `~/.cache/luminous`)."""


def canonical_build_dir() -> Path:
    """Where `luminous eval --split` keeps the canonical build of the frozen splits when no `--build` folder is
    named: `$LUMINOUS_CACHE/benchmark-v<SPLIT_VERSION>`, else `~/.cache/luminous/benchmark-v<SPLIT_VERSION>`
    (a new split version gets a new folder; nothing is written outside it)."""
    import os

    root = Path(os.environ.get(CACHE_VAR) or Path.home() / ".cache" / "luminous")
    return root / f"benchmark-v{SPLIT_VERSION}"


def manifest_path(split: str, folder: Path = DATA_DIR) -> Path:
    """Where split `split`'s manifest is (`S+.jsonl`, ...)."""
    return Path(folder) / f"{split}.jsonl"


@dataclass(frozen=True)
class BenchmarkEntry:
    """Episode `index` of a frozen split: where it happens, what is asked, where the agent starts."""

    split: str
    index: int
    task_type: str
    floor_plan: str
    room_type: str
    layout: int
    layout_seed: int
    draw: int
    """Which draw in its layout this is (0, 1, ...; the ones before were rejected or belong to other entries)."""
    task_seed: int
    pddl_params: dict[str, Any]
    start: AgentPose
    repeat: bool
    """The same task as an earlier entry of the layout, from another start (its layouts were out of tasks)."""
    episode_key: str

    @property
    def layout_of(self) -> Layout:
        return Layout(self.floor_plan, self.room_type, self.layout, self.layout_seed)


@lru_cache(maxsize=len(FROZEN))
def _manifest(split: str) -> tuple[dict[str, Any], tuple[BenchmarkEntry, ...]]:
    plus_split(split)
    path = manifest_path(split)
    if split not in FROZEN or not path.is_file():
        raise SplitError(f"split {split} is not frozen yet (frozen: {', '.join(FROZEN)}); freeze it with "
                         f"python -m luminous_sim.benchmark.freeze --split {split}")
    lines = path.read_text().splitlines()
    header = json.loads(lines[0])
    if header.get("format") != FROZEN_FORMAT or header.get("version") != SPLIT_VERSION:
        raise SplitError(f"{path}: format {header.get('format')!r} version {header.get('version')!r}; this "
                         f"package reads {FROZEN_FORMAT} version {SPLIT_VERSION}")
    entries = []
    for i, line in enumerate(lines[1:]):
        e = json.loads(line)
        x, y, rotation, horizon = e["start"]
        entries.append(BenchmarkEntry(split, i, e["task_type"], e["floor_plan"], e["room_type"], e["layout"],
                                      e["layout_seed"], e["draw"], e["task_seed"], e["pddl_params"],
                                      AgentPose(x, y, int(rotation), int(horizon)), e["repeat"], e["episode_key"]))
        if e["index"] != i:
            raise SplitError(f"{path}: line {i + 2}: index {e['index']}, expected {i}")
    return header, tuple(entries)


def frozen_header(split: str) -> dict[str, Any]:
    """The header of a split's manifest: counts per type, rejections per type and cause, repeats, version.

    Raises:
        SplitError: an unknown or unfrozen split.
    """
    return _manifest(split)[0]


def benchmark_size(split: str) -> int:
    """Episodes in a frozen split."""
    return len(_manifest(split)[1])


def benchmark_entry(split: str, index: int) -> BenchmarkEntry:
    """Entry `index` of split `split`.

    Raises:
        SplitError: an unknown or unfrozen split, or an index outside it.
    """
    entries = _manifest(split)[1]
    if not 0 <= index < len(entries):
        raise SplitError(f"split {split}: episode index {index} is outside 0..{len(entries) - 1} "
                         f"(the split holds {len(entries)} episodes)")
    return entries[index]


def benchmark_entries(split: str, count: int | None = None, start: int = 0) -> list[BenchmarkEntry]:
    """Entries `start .. start + count - 1` (all from `start` when `count` is None)."""
    end = benchmark_size(split) if count is None else start + count
    return [benchmark_entry(split, i) for i in range(start, end)]
