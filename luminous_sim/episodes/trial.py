"""A built trial as an episode, restored from its files alone (`benchmark.read_trial`), as ALFRED's evaluation
restores one from its traj_data: its scene, task and start, ALFRED's set-up when the trial says so
(`dirty_and_empty`), the goal reading annotation 0's directive, and the recorded expert's actions as the
plan (its length is L*, its steps the annotation's step instructions)."""

from __future__ import annotations

from luminous_sim.benchmark import TrialEpisode
from luminous_sim.episodes.goals import ExpertPlan, TaskGoal
from luminous_sim.episodes.initial_state import WorldSource, alfred_set_up
from luminous_sim.episodes.spec import EpisodeSpec
from luminous_sim.world import World


def trial_spec(trial: TrialEpisode, worlds: WorldSource, with_plan: bool = True) -> tuple[EpisodeSpec, World]:
    """The trial's episode and its world, ready for the first step; `with_plan`: the recorded actions as the
    expert's plan."""
    world = worlds.get(trial.scene)
    dirty = alfred_set_up(world, trial.task.task_type) if trial.dirty_and_empty else ()
    world.set_start(trial.start)
    plan = ExpertPlan(trial.api_actions, exact=True, steps=trial.steps) if with_plan else None
    return EpisodeSpec(trial.scene, TaskGoal(trial.task), dirty, plan, start=trial.start), world
