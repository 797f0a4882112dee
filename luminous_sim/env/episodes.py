"""Drawing an episode: a scene (generated on the fly, given, or an entry of an evaluation split), a goal
that fits it physically, and (optionally) the expert's plan, which also proves the episode solvable, as
ALFRED's generator keeps only tasks its expert solves.

Scenes come from CSSG (`TaskKind.generate_scene`, by default `cssg.generate(empty_cdf(room_type), seed)`):
layer L4 may use the generator, as task-driven generation in `luminous_sim.data` does (this module repeats
the small part of that it needs rather than import layer L5). A drawn scene whose task does not fit is
replaced by a new one, a bounded number of times (`EnvConfig.scene_attempts`).

An entry of a frozen split (`luminous_sim.benchmark`: S+, U+, U+test) fixes everything instead: its
scene, task, initial state and start are `benchmark.entry_episode(entry)`, the one definition every user of
a split calls (dataset builds, evaluation, behaviour cloning). Every split entry has an episode (the split
holds only episodes the oracle solved); with `verify_expert`, an expert that does not solve one in this env
(another camera, say) raises `EpisodeUnavailable` (cause `expert`), which an evaluation counts as a failure.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from luminous_sim.benchmark import (
    BenchmarkEntry,
    TrialEpisode,
    benchmark_entries,
    benchmark_entry,
    entry_episode,
    episode_key,
)
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.goals import ExpertPlan, Goal
from luminous_sim.env.kinds import set_up, task_kind
from luminous_sim.env.reset_options import ResetOptions
from luminous_sim.env.worlds import WorldPool
from luminous_sim.errors import InfeasibleSceneError, LuminousError
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskSamplingError
from luminous_sim.world import AgentPose, World

UNAVAILABLE_CAUSES: tuple[str, ...] = ("expert",)
"""Why a split entry has no episode in an env: its expert does not solve it there (the split's oracle did, at
ALFRED's camera)."""


class EpisodeUnavailable(LuminousError):
    """A split entry whose episode cannot be drawn; `cause` is one of `UNAVAILABLE_CAUSES`."""

    def __init__(self, entry: BenchmarkEntry, cause: str, detail: str):
        super().__init__(f"{entry.split} episode {entry.index} ({entry.task_type} in {entry.floor_plan}, "
                         f"layout {entry.layout}): {detail}")
        self.entry, self.cause, self.detail = entry, cause, detail

    def __reduce__(self) -> tuple[Any, ...]:  # crosses process boundaries in an evaluation's workers
        return (type(self), (self.entry, self.cause, self.detail))


@dataclass(frozen=True)
class Episode:
    """One episode's set-up: a world of its scene at its start, set up with `dirty`, is the episode's world."""

    scene: Scene
    goal: Goal
    dirty: tuple[str, ...] = ()
    """Objects made dirty before the first step (ALFRED's set-up for a cleaning task)."""
    expert: ExpertPlan | None = None
    redraws: int = 0
    """Draws rejected before this one: a scene CSSG could not lay out, no task of the type fitted, or (with
    `verify_expert`) the expert did not solve the task drawn."""
    start: AgentPose | None = None
    """Where the agent starts (a CDF's `task.agent`); None for the world's default start."""
    key: str = ""
    """`benchmark.episode_key` of the episode (its scene, task, initial state and start)."""


def set_up_world(world: World, task_type: str) -> tuple[str, ...]:
    """Set a world up for an episode of the kind (`TaskKind.set_up`: e.g. for cleaning, everything dirtyable
    dirty); the objects it made dirty."""
    dirty = set_up(world, task_type)
    if dirty:
        world.set_up_dirty(dirty)
    return dirty


def room_types(config: EnvConfig, task_type: str) -> list[str]:
    """The room types an episode of the kind may be generated in (`TaskKind.rooms`, the config's choice).

    Raises:
        LuminousError: the config's room types leave none (`check_rooms` refuses such a config up front).
    """
    allowed = list(task_kind(task_type).rooms())
    chosen = [r for r in allowed if not config.room_types or r in config.room_types]
    if not chosen:
        raise LuminousError(_unfit([task_type], config.room_types))
    return chosen


def check_rooms(config: EnvConfig) -> None:
    """Refuse room types that cannot go with the task types (each kind's `rooms()`, ALFRED's table for its
    types): a task type played in none of them, or a room type no task type is played in. Nothing is
    checked without room types (each task type then goes to every room it allows).

    Raises:
        LuminousError: one line naming the task types that do not fit, the room types and the rooms each
            allows (or the room types no task type uses).
    """
    if not config.room_types:
        return
    chosen = set(config.room_types)
    types = list(dict.fromkeys(config.task_types))
    unfit = [t for t in types if not chosen.intersection(task_kind(t).rooms())]
    if unfit:
        raise LuminousError(_unfit(unfit, config.room_types))
    used = {r for t in types for r in task_kind(t).rooms()}
    idle = [r for r in dict.fromkeys(config.room_types) if r not in used]
    if idle:
        raise LuminousError(f"env config room_types: no task of {', '.join(types)} is played in "
                            f"{', '.join(idle)}; drop {'it' if len(idle) == 1 else 'them'}")


def _unfit(task_types: list[str], rooms: tuple[str, ...]) -> str:
    """The message for task types played in none of the config's room types."""
    where = "; ".join(f"{t} is played only in {', '.join(task_kind(t).rooms())}" for t in task_types)
    return (f"env config room_types: {', '.join(rooms)} allow{'s' if len(rooms) == 1 else ''} no "
            f"{' or '.join(task_types)} task ({where}); add one of those room types or drop the task type from "
            "task_types")


def draw_goal(world: World, scene: Scene, task_type: str, rng: np.random.Generator,
              options: dict[str, float] | None = None) -> Goal:
    """A goal of the kind that fits this world (`TaskKind.draw_goal`, the kind configured with `options`).

    Raises:
        TaskSamplingError: none fits.
    """
    return task_kind(task_type).configured(options or {}).draw_goal(world, scene, rng)


def draw_start(world: World, goal: Goal, task_type: str, rng: np.random.Generator,
               options: dict[str, float] | None = None) -> AgentPose | None:
    """The kind's start for the goal (`TaskKind.draw_start`), set in `world`; None keeps the default start.

    Raises:
        TaskSamplingError: no start fits.
    """
    start = task_kind(task_type).configured(options or {}).draw_start(world, goal, rng)
    if start is not None:
        world.set_start(start)
    return start


def _prove(episode: Episode, worlds: WorldPool) -> ExpertPlan | None:
    """The expert's plan if it solves the episode in a world of its own, and its replay does too."""
    shadow = worlds.get(episode.scene, episode.dirty, episode.start)
    try:
        plan = episode.goal.expert_plan(shadow)
    finally:
        worlds.put(shadow)
    if plan is None or plan.exact:
        return plan
    replay = worlds.get(episode.scene, episode.dirty, episode.start)
    try:
        ok = all(replay.step(a).success for a in plan.actions)
        view = replay.view()
        scores = episode.goal.scores(view, set(view.visible_objects()))
        ok = ok and scores == episode.goal.weights()
    finally:
        worlds.put(replay)
    return ExpertPlan(plan.actions, exact=True, steps=plan.steps) if ok else None


def draw_episode(config: EnvConfig, rng: np.random.Generator, worlds: WorldPool,
                 scene: Scene | None = None) -> tuple[Episode, World]:
    """An episode and its world, ready for the first step (same rng state, same episode).

    Args:
        config: the environment.
        rng: every draw comes from it.
        worlds: where worlds come from (and go back to).
        scene: use this scene (only the goal is drawn) instead of generating one.

    Raises:
        LuminousError: no attempt gave an episode that fits (the message lists why).
    """
    why: list[str] = []
    for _ in range(config.scene_attempts):
        task_type = config.task_types[int(rng.integers(len(config.task_types)))]
        if scene is None:
            rooms = room_types(config, task_type)
            room = rooms[int(rng.integers(len(rooms)))]
            seed = int(rng.integers(2**31))
            try:
                candidate = task_kind(task_type).configured(config.task_options).generate_scene(room, seed)
            except InfeasibleSceneError as exc:
                why.append(f"{room} seed {seed}: {exc}")
                continue
        else:
            candidate = scene
        world = worlds.get(candidate)
        dirty = set_up_world(world, task_type)
        try:
            goal = draw_goal(world, candidate, task_type, rng, config.task_options)
            start = draw_start(world, goal, task_type, rng, config.task_options)
        except TaskSamplingError as exc:
            worlds.put(world)
            why.append(str(exc))
            continue
        episode = Episode(candidate, goal, dirty, redraws=len(why), start=start)
        if config.verify_expert:
            plan = _prove(episode, worlds)
            if plan is None:
                worlds.put(world)
                why.append(f"the expert does not solve {goal.instruction!r} in {candidate.room.name} "
                           f"(seed {candidate.seed})")
                continue
            episode = Episode(candidate, goal, dirty, plan, len(why), start)
        return episode, world
    raise LuminousError(f"no episode of {', '.join(config.task_types)} after {config.scene_attempts} attempts: "
                        + "; ".join(why[-3:]))


def content_key(episode: Episode, world: World) -> str:
    """`benchmark.episode_key` of an episode (a goal that is no task is keyed by its `to_dict` data)."""
    from luminous_sim.env.goals import TaskGoal

    goal = episode.goal
    params = goal.task.params.to_json() if isinstance(goal, TaskGoal) else goal.to_dict()
    return episode_key(episode.scene, goal.task_type, params, episode.start or world.agent, episode.dirty)


def requested_entry(config: EnvConfig, options: ResetOptions, rng: np.random.Generator) -> BenchmarkEntry | None:
    """The split entry a reset asks for (`options.split`, else `config.split`; `options.index`, else one drawn
    from `rng` over the split's entries of the env's task types), or None for an episode from elsewhere (a
    scene or a CDF the options name, the env's CDFs, or generated on the fly).

    Raises:
        LuminousError: an entry of a task type the env does not play, or a split with none of them.
    """
    if options.source not in ("", "split"):
        return None
    name = options.split or config.split
    if not name:
        return None
    index = options.index
    if index is None:
        mine = [e.index for e in benchmark_entries(name) if e.task_type in config.task_types]
        if not mine:
            raise LuminousError(f"split {name} holds no episode of {', '.join(config.task_types)}")
        index = mine[int(rng.integers(len(mine)))]
    entry = benchmark_entry(name, index)
    if entry.task_type not in config.task_types:
        raise LuminousError(f"{name} episode {index} is a {entry.task_type} task; this env plays only "
                            f"{', '.join(config.task_types)}")
    return entry


def split_episode(config: EnvConfig, entry: BenchmarkEntry, worlds: WorldPool) -> tuple[Episode, World]:
    """The episode of a split entry (`benchmark.entry_episode`) and its world, ready for the first step.

    Raises:
        SplitVersionError: this checkout makes another episode than the frozen split.
        EpisodeUnavailable: with `verify_expert`, the expert does not solve it in this env (cause `expert`).
    """
    from luminous_sim.env.goals import TaskGoal

    made = entry_episode(entry)
    episode = Episode(made.scene, TaskGoal(made.task), made.dirty, start=made.start)
    world = worlds.get(made.scene, made.dirty, made.start)
    if not config.verify_expert:
        return episode, world
    plan = _prove(episode, worlds)
    if plan is None:
        worlds.put(world)
        raise EpisodeUnavailable(entry, "expert", f"the expert does not solve {made.task.instruction!r} in this env")
    return Episode(made.scene, episode.goal, made.dirty, plan, start=made.start), world


def trial_episode(config: EnvConfig, trial: TrialEpisode, worlds: WorldPool) -> tuple[Episode, World]:
    """The episode of a built trial, restored from its files alone (`benchmark.read_trial`): its
    scene, task, start and ALFRED's set-up; the goal reads annotation 0's directive, and the expert's plan is
    the recorded one (its length is L*, its steps the annotation's step instructions), as ALFRED's evaluation
    takes L* from the trajectory it replays.

    """
    from luminous_sim.env.goals import TaskGoal

    world = worlds.get(trial.scene)
    dirty = set_up_world(world, trial.task.task_type) if trial.dirty_and_empty else ()
    world.set_start(trial.start)
    plan = ExpertPlan(trial.api_actions, exact=True, steps=trial.steps) if config.verify_expert else None
    return Episode(trial.scene, TaskGoal(trial.task), dirty, plan, start=trial.start), world
