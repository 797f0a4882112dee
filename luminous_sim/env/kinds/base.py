"""`TaskKind`: one kind of env task (an ALFRED type, `goto_object`, `pickup_object`) behind fixed hooks, as a
ManiSkill task overrides a few: the room types it is played in, its set-up before the episode (what to make
dirty), drawing its goal in a world, and reading that goal back from plain data.

A new kind is one module in this package with a `TaskKind` subclass, and one line in the registry
(`luminous_sim.env.kinds`).
"""

from __future__ import annotations

import copy
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any

from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ROOM_TYPES

if TYPE_CHECKING:
    import numpy as np

    from luminous_sim.episodes import Goal
    from luminous_sim.scene import Scene
    from luminous_sim.world import AgentPose, World


class TaskKind(ABC):
    """A kind of task, with default hooks (every room type, no set-up); subclasses override what differs.

    Attributes:
        name: the kind's name, as `EnvConfig.task_types` and `info["task_type"]` give it.
        templates: instruction templates of the kind's own goals (their words join the token vocabulary).
        defaults: the kind's options (`EnvConfig.task_options`) and their values when a config gives none,
            as the kind's model in `kinds.options` declares them (checking a config imports no kind).
        options: the options in force (`configured`).
    """

    templates: tuple[str, ...] = ()

    def __init__(self, name: str):
        from luminous_sim.env.kinds.options import kind_defaults

        self.name = name
        self.defaults: Mapping[str, float] = kind_defaults(name)
        self.options: Mapping[str, float] = dict(self.defaults)

    def configured(self, options: Mapping[str, float]) -> TaskKind:
        """This kind with the options it takes from `options` (others are left to other kinds)."""
        mine = {k: float(v) for k, v in options.items() if k in self.defaults}
        if not mine:
            return self
        kind = copy.copy(self)
        kind.options = {**self.defaults, **mine}
        return kind

    def rooms(self) -> tuple[str, ...]:
        """The room types an episode of this kind may be generated in."""
        return ROOM_TYPES

    def generate_scene(self, room_type: str, seed: int) -> Scene:
        """A scene for an episode generated on the fly (the room type drawn from `rooms`, the seed drawn too):
        by default CSSG lays out one room of the type; a kind may generate something else (a house).

        Raises:
            InfeasibleSceneError: no scene could be laid out for the seed.
        """
        from luminous_sim.cssg import empty_cdf, generate

        return generate(empty_cdf(room_type), seed=seed).scene

    def set_up(self, world: World) -> tuple[str, ...]:
        """The objects to make dirty before the episode (in `world`, as built); none by default."""
        return ()

    @abstractmethod
    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        """A goal of this kind that fits `world` (set up), every draw from `rng` (every kind defines it).

        Raises:
            TaskSamplingError: none fits.
        """

    def draw_start(self, world: World, goal: Goal, rng: np.random.Generator) -> AgentPose | None:
        """Where the agent starts, drawn for `goal` in `world` (set up); None (the default) keeps the world's
        default start.

        Raises:
            TaskSamplingError: no start fits the goal.
        """
        return None

    def goal_from_dict(self, data: dict[str, Any]) -> Goal:
        """The goal of `Goal.to_dict` data whose `kind` is this kind's name (a `TaskGoal` reads back as a task
        and never comes here)."""
        raise LuminousError(f"task kind {self.name}: its goals are tasks (kind 'task'), got {data.get('kind')!r}")


def unseen_type(world: World, scene: Scene, kind: str, worthy: Callable[[str], bool],
                rng: np.random.Generator) -> str:
    """An object type to find: one of the `worthy` types of the objects that can be seen from somewhere but
    that no object in view at the start has (drawn uniformly from their sorted list).

    Raises:
        TaskSamplingError: no type qualifies.
    """
    from luminous_sim.planning import unseeable
    from luminous_sim.tasks import TaskSamplingError

    view = world.view()
    hidden = unseeable(view)
    seen = {view.state.objects[o].object_type for o in view.visible_objects() if o in view.state.objects}
    types = sorted({st.object_type for oid, st in view.state.objects.items() if oid not in hidden
                    and st.object_type not in seen and worthy(st.object_type)})
    if not types:
        raise TaskSamplingError(f"no {kind} target in {scene.room.name} (seed {scene.seed})")
    return types[int(rng.integers(len(types)))]
