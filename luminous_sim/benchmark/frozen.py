"""The frozen splits: each split's manifest, shipped in `luminous_sim/benchmark/data/<split>.jsonl` (a header
line, then one line per episode: task type, layout, draw and its seed, task parameters, start, `episode_key`),
read here. Entry `i` of a split is line `i + 1`, the same on every machine. Each manifest's SHA-256 lives in code
(`MANIFEST_SHA256`) and is checked before the manifest is read: a changed, truncated or renumbered manifest is
refused with a message, never taken for another benchmark (nor cached as a build failure)."""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from luminous_sim.benchmark.counts import Layout
from luminous_sim.resources import cache_root
from luminous_sim.splits import SplitError, plus_split
from luminous_sim.world import AgentPose

FROZEN_FORMAT = "luminous-frozen-split/1"
SPLIT_VERSION = 1
"""The version of the frozen splits; a generator change that changes their episodes makes a new one."""
DATA_DIR = Path(__file__).parent / "data"
FROZEN = ("S+", "U+")
"""The splits that are frozen (their manifests ship with the package). U+test (`PAPER_COUNTS` has its counts) is
not frozen yet: its entries are refused with a message saying so."""
MANIFEST_SHA256 = {
    "S+": "14e34e745573f7c54f2ee44efc17f17db0423a5dda048508d765eb3a85a9d550",
    "U+": "37c15c1979567ad4ce5831d5f66a9d6d8a4a77264f5524e0965c2aff1dc70122",
}
"""The shipped manifests' SHA-256 (of their bytes). Freezing a split again (`episodes.freeze`) changes it: put the
new value here."""


def canonical_build_dir(split: str) -> Path:
    """Where `luminous eval --split` keeps the canonical build of frozen split `split` when no `--build` folder is
    named: `<cache>/benchmark-v<SPLIT_VERSION>/<split>-<first 16 digits of its manifest's digest>` under
    `luminous_sim.resources.cache_root()` (`$LUMINOUS_CACHE`, `$XDG_CACHE_HOME/luminous` or `~/.cache/luminous`).
    Keyed by the split version and the manifest, not the package version: a patch release does not build S+
    again, and a new manifest never reads the old one's trials.

    Raises:
        SplitError: an unknown or unfrozen split.
    """
    if split not in MANIFEST_SHA256:
        plus_split(split)
        raise SplitError(f"split {split} is not frozen yet (frozen: {', '.join(FROZEN)})")
    return cache_root() / f"benchmark-v{SPLIT_VERSION}" / f"{split}-{MANIFEST_SHA256[split][:16]}"


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
                         f"python -m luminous_sim.episodes.freeze --split {split}")
    data = path.read_bytes()
    digest = hashlib.sha256(data).hexdigest()
    if digest != MANIFEST_SHA256[split]:
        raise SplitError(f"{path}: the frozen manifest of {split} was changed (sha256 {digest[:16]}..., shipped "
                         f"{MANIFEST_SHA256[split][:16]}...); reinstall luminous-sim (pip install --force-reinstall "
                         "luminous-sim) or restore the file (git checkout)")
    lines = data.decode().splitlines()
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
