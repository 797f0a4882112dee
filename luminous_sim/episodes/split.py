"""A frozen split's entry as an episode, the one definition (`dataset build --split`, `luminous eval --split`,
the env's `reset(options={"split": ..., "index": i})`, behaviour cloning): entry `i`'s layout is made by CSSG
from its seed, its task and start are drawn again from the entry's seed (`benchmark.draw`) in a world set up
as ALFRED sets one up, and the result's `episode_key` must equal the one frozen in the manifest: a checkout whose
generator, sampler or set-up makes anything else refuses to play it (`SplitVersionError`) instead of silently
playing another benchmark."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from luminous_sim.benchmark import SPLIT_VERSION, BenchmarkEntry, draw, layout_scene
from luminous_sim.episodes.expert_proof import solve
from luminous_sim.episodes.goals import TaskGoal
from luminous_sim.episodes.initial_state import WorldSource, alfred_set_up
from luminous_sim.episodes.spec import EpisodeSpec
from luminous_sim.errors import LuminousError
from luminous_sim.world import World

FREEZE_COMMAND = "python -m luminous_sim.episodes.freeze"
UNAVAILABLE_CAUSES: tuple[str, ...] = ("expert",)
"""Why a split entry has no episode in an env: its expert does not solve it there (the split's oracle did, at
ALFRED's camera)."""


class SplitVersionError(LuminousError):
    """This checkout makes a different episode than the frozen split says (the generator changed)."""


class EpisodeUnavailable(LuminousError):
    """A split entry whose episode cannot be drawn; `cause` is one of `UNAVAILABLE_CAUSES`."""

    def __init__(self, entry: BenchmarkEntry, cause: str, detail: str):
        super().__init__(f"{entry.split} episode {entry.index} ({entry.task_type} in {entry.floor_plan}, "
                         f"layout {entry.layout}): {detail}")
        self.entry, self.cause, self.detail = entry, cause, detail

    def __reduce__(self) -> tuple[Any, ...]:  # crosses process boundaries in an evaluation's workers
        return (type(self), (self.entry, self.cause, self.detail))


def entry_spec(entry: BenchmarkEntry) -> EpisodeSpec:
    """The episode of a frozen split's entry (the same on every machine), keyed.

    Raises:
        SplitVersionError: the layout, task, start or initial state made here differ from the frozen ones.
    """
    from luminous_sim.errors import InfeasibleSceneError
    from luminous_sim.tasks import TaskSamplingError

    where = (f"{entry.split} episode {entry.index} ({entry.task_type} in {entry.floor_plan} layout {entry.layout}, "
             f"split version {SPLIT_VERSION})")
    try:
        scene = layout_scene(entry.floor_plan, entry.room_type, entry.layout_seed)
    except InfeasibleSceneError as exc:
        raise SplitVersionError(f"{where}: CSSG no longer lays the structure out ({exc}); the generator changed "
                                "and the split needs a new version") from None
    world = World(scene)
    try:
        dirty = alfred_set_up(world, entry.task_type)
        drawn = draw(scene, world, entry.task_type, entry.task_seed, dirty)
    except TaskSamplingError as exc:
        raise SplitVersionError(f"{where}: no task of the type is drawn any more ({exc})") from None
    finally:
        world.close()
    if drawn.key != entry.episode_key:
        what = ("the task" if drawn.task.params.to_json() != entry.pddl_params else
                "the start" if drawn.start != entry.start else "the scene or the initial state")
        raise SplitVersionError(f"{where}: this checkout makes another episode ({what} differs: key {drawn.key}, "
                                f"frozen {entry.episode_key}); the generator, sampler or set-up changed, so the "
                                f"split needs a new version ({FREEZE_COMMAND})")
    return EpisodeSpec(scene, TaskGoal(drawn.task), drawn.dirty, start=drawn.start, key=drawn.key)


def entry_episode(entry: BenchmarkEntry) -> EpisodeSpec:
    """`entry_spec` under its old name (`benchmark.entry_episode`, which forwards here until 0.3.0)."""
    return entry_spec(entry)


def split_spec(entry: BenchmarkEntry, worlds: WorldSource, verify_expert: bool) -> tuple[EpisodeSpec, World]:
    """The entry's episode (`entry_spec`) and its world, ready for the first step; with `verify_expert`, with
    the expert's plan from a world of the source (its camera may not be ALFRED's, at which the split's oracle
    solved it).

    Raises:
        SplitVersionError: this checkout makes another episode than the frozen split.
        EpisodeUnavailable: with `verify_expert`, the expert does not solve it here (cause `expert`).
    """
    spec = entry_spec(entry)
    world = worlds.get(spec.scene, spec.dirty, spec.start)
    if not verify_expert:
        return spec, world
    plan = solve(spec, worlds).plan
    if plan is None:
        worlds.put(world)
        raise EpisodeUnavailable(entry, "expert", f"the expert does not solve {spec.task.instruction!r} in this env")
    return replace(spec, expert=plan), world
