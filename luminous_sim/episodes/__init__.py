"""Layer L4: episodes, one home (habitat-lab's Dataset/Episode pattern). An episode is an `EpisodeSpec` (scene,
goal, ALFRED's set-up, start, key); `prepare` puts a world in its initial state (`alfred_set_up`: ALFRED's
set-up, the only copy); `solve` says whether the expert solves it (the only check); sources draw specs:
generated on the fly or in a given scene (`draw_generated`, a house when the kind is set so), a frozen split's
entry (`entry_spec`, `split_spec`), a built trial (`trial_spec`), a CDF file (`draw_from_cdf`). The env's
reset, `dataset build`, `luminous eval`, `episode.run_task`, the thor controller and behaviour cloning all draw
from here; the freeze that drew the splits is `python -m luminous_sim.episodes.freeze`.

Typical use::

    from luminous_sim.benchmark import benchmark_entry
    from luminous_sim.episodes import FreshWorlds, entry_spec, solve
    spec = entry_spec(benchmark_entry("U+", 0))
    print(spec.task.instruction, spec.key, solve(spec, FreshWorlds()).cause or "solved")

Public names load on first use (the simulator only when a world is made).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.episodes.cdf import cdf_scene, draw_from_cdf, load_cdf, start_pose
    from luminous_sim.episodes.expert_proof import Solution, solve
    from luminous_sim.episodes.generated import Drawing, Kind, draw_generated
    from luminous_sim.episodes.goals import ExpertPlan, Goal, TaskGoal
    from luminous_sim.episodes.initial_state import FreshWorlds, WorldSource, alfred_set_up, prepare, set_initial
    from luminous_sim.episodes.spec import EpisodeSpec, keyed
    from luminous_sim.episodes.split import (
        UNAVAILABLE_CAUSES,
        EpisodeUnavailable,
        SplitVersionError,
        entry_spec,
        split_spec,
    )
    from luminous_sim.episodes.trial import trial_spec



_WHERE = {
    "EpisodeSpec": "spec", "keyed": "spec", "BenchmarkEpisode": "spec",
    "ExpertPlan": "goals", "Goal": "goals", "TaskGoal": "goals",
    "prepare": "initial_state", "set_initial": "initial_state", "alfred_set_up": "initial_state",
    "WorldSource": "initial_state",
    "FreshWorlds": "initial_state",
    "solve": "expert_proof", "Solution": "expert_proof",
    "Drawing": "generated", "Kind": "generated", "draw_generated": "generated",
    "draw_from_cdf": "cdf", "load_cdf": "cdf", "cdf_scene": "cdf", "start_pose": "cdf",
    "entry_spec": "split", "split_spec": "split", "SplitVersionError": "split", "EpisodeUnavailable": "split",
    "UNAVAILABLE_CAUSES": "split",
    "trial_spec": "trial",
}

__all__ = [
    "UNAVAILABLE_CAUSES",
    "Drawing",
    "EpisodeSpec",
    "EpisodeUnavailable",
    "ExpertPlan",
    "FreshWorlds",
    "Goal",
    "Kind",
    "Solution",
    "SplitVersionError",
    "TaskGoal",
    "WorldSource",
    "alfred_set_up",
    "cdf_scene",
    "draw_from_cdf",
    "draw_generated",
    "entry_spec",
    "keyed",
    "load_cdf",
    "prepare",
    "set_initial",
    "solve",
    "split_spec",
    "start_pose",
    "trial_spec",
]

__getattr__ = lazy_getattr(__name__, _WHERE)
