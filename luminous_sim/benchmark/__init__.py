"""Layer L4: LUMINOUS's S+/U+ as one frozen benchmark, as data. Entry `i` of a split is line `i` of the split's
shipped manifest (`frozen`): its layout (`layout_scene`), the seed its task and start are drawn from
(`draw`), and its `episode_key` (a digest of that content, which lets anyone check that two runs played the
same episode); a built trial is read back from its files (`read_trial`). The entry made into an episode is
`luminous_sim.episodes.entry_spec`, which every user calls.

Typical use::

    from luminous_sim.benchmark import benchmark_entry
    from luminous_sim.episodes import entry_spec
    spec = entry_spec(benchmark_entry("U+", 0))
    print(spec.task.instruction, spec.key)
"""

from luminous_sim.benchmark.counts import PAPER_COUNTS, Layout, split_layouts, type_counts
from luminous_sim.benchmark.draw import Draw, draw, layout_scene
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
from luminous_sim.lazy import moved_getattr

__all__ = [
    "FROZEN",
    "PAPER_COUNTS",
    "SPLIT_VERSION",
    "BenchmarkEntry",
    "Draw",
    "Layout",
    "TrialEpisode",
    "TrialError",
    "benchmark_entries",
    "benchmark_entry",
    "benchmark_size",
    "canonical_build_dir",
    "draw",
    "episode_key",
    "frozen_header",
    "layout_scene",
    "read_trial",
    "split_layouts",
    "start_fields",
    "trial_folders",
    "type_counts",
]

__getattr__ = moved_getattr(__name__, {"entry_episode": "luminous_sim.episodes.split",
                                       "BenchmarkEpisode": "luminous_sim.episodes",
                                       "SplitVersionError": "luminous_sim.episodes"}, "0.3.0")
