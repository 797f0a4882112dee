"""Layer L4: LUMINOUS's S+/U+ as one frozen benchmark. One definition of an episode: entry `i` of a split is
line `i` of the split's shipped manifest (`frozen`), made into a scene, a task, an initial state and a start
by `episode.entry_episode`, which every user calls (`dataset build --split`, `luminous eval --split`, the
env's `reset(options={"split": ..., "index": i})`, the BC benchmark); `episode_key` (a digest of that
content) lets anyone check that two runs played the same episode.

Typical use::

    from luminous_sim.benchmark import benchmark_entry, entry_episode
    episode = entry_episode(benchmark_entry("U+", 0))
    print(episode.task.instruction, episode.key)
"""

from luminous_sim.benchmark.counts import PAPER_COUNTS, Layout, split_layouts, type_counts
from luminous_sim.benchmark.draw import layout_scene
from luminous_sim.benchmark.episode import BenchmarkEpisode, SplitVersionError, entry_episode
from luminous_sim.benchmark.frozen import (
    FROZEN,
    SPLIT_VERSION,
    BenchmarkEntry,
    benchmark_entries,
    benchmark_entry,
    benchmark_size,
    canonical_build_dir,
    frozen_header,
)
from luminous_sim.benchmark.key import episode_key, start_fields
from luminous_sim.benchmark.trial import TrialEpisode, TrialError, read_trial, trial_folders

__all__ = [
    "FROZEN",
    "PAPER_COUNTS",
    "SPLIT_VERSION",
    "BenchmarkEntry",
    "BenchmarkEpisode",
    "Layout",
    "SplitVersionError",
    "TrialEpisode",
    "TrialError",
    "benchmark_entries",
    "benchmark_entry",
    "benchmark_size",
    "canonical_build_dir",
    "entry_episode",
    "episode_key",
    "frozen_header",
    "layout_scene",
    "read_trial",
    "split_layouts",
    "start_fields",
    "trial_folders",
    "type_counts",
]
