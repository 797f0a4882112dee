"""`EpisodeSpec`: what every user of an episode plays (the env's reset, a dataset build, an evaluation, the thor
controller, behaviour cloning): a scene, a goal, ALFRED's set-up (the objects made dirty) and the agent's start;
with what its source learned while drawing it (the expert's plan, the draws rejected before it)."""

from __future__ import annotations

from dataclasses import dataclass

from luminous_sim.episodes.goals import ExpertPlan, Goal, TaskGoal
from luminous_sim.errors import LuminousError
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskInstance
from luminous_sim.world import AgentPose


@dataclass(frozen=True)
class EpisodeSpec:
    """One episode: a world of `scene` prepared with `dirty` and the agent at `start` (`episodes.prepare`) is
    the episode's world; `goal` is what is asked."""

    scene: Scene
    goal: Goal
    dirty: tuple[str, ...] = ()
    """Objects made dirty before the first step (ALFRED's set-up for a cleaning task)."""
    expert: ExpertPlan | None = None
    """The expert's plan from the start, when the source proved it (`episodes.solve`) or recorded it."""
    redraws: int = 0
    """Draws rejected before this one: a scene CSSG could not lay out, no task of the type fitted, or (with
    the expert's proof asked for) the expert did not solve the task drawn."""
    start: AgentPose | None = None
    """Where the agent starts; None for the world's default start."""
    key: str = ""
    """`benchmark.episode_key` of the episode (its scene, task, initial state and start); "" until keyed."""

    @property
    def task(self) -> TaskInstance:
        """The task of a task goal (ALFRED's seven types, a CDF's task, `pickup_object`).

        Raises:
            LuminousError: the goal is a kind's own (ObjectNav, go-to), not a task.
        """
        if not isinstance(self.goal, TaskGoal):
            raise LuminousError(f"a {self.goal.task_type} episode's goal is not a task")
        return self.goal.task


def keyed(spec: EpisodeSpec, default_start: AgentPose) -> EpisodeSpec:
    """The spec with its `benchmark.episode_key` (a goal that is no task is keyed by its `to_dict` data; no start
    is keyed as `default_start`, the world's); a keyed spec as it is."""
    from dataclasses import replace

    from luminous_sim.benchmark import episode_key

    if spec.key:
        return spec
    goal = spec.goal
    params = goal.task.params.to_json() if isinstance(goal, TaskGoal) else goal.to_dict()
    return replace(spec, key=episode_key(spec.scene, goal.task_type, params, spec.start or default_start, spec.dirty))


BenchmarkEpisode = EpisodeSpec
"""The old name of a split entry's episode (`benchmark.BenchmarkEpisode` forwards here until 0.3.0)."""
