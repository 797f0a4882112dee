"""Which of a scene's symbolically feasible tasks its world can physically support.

The task sampler reasons over types and the compatibility table (a Pan may go in a Cabinet); the
world knows that this 35 cm deep wall cabinet is too shallow for this pan, and that the side table is
already covered. ALFRED's generator drops tasks its expert fails; we rule most of them out up front.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np

from luminous_sim.errors import Failure
from luminous_sim.scene import Scene
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.sample import sample_task
from luminous_sim.vocab import parent_type
from luminous_sim.world import WorldView

SPOT_SEED = 2024
"""Seed of the dry-run placements (kept apart from the world's own random stream)."""


def _hosts(state, receptacle_type: str, full: Iterable[str]) -> list[str] | None:
    """The receptacles of a type other than the `full` ones; None when it has some and all are full."""
    every = state.of_type(receptacle_type)
    full = set(full)
    hosts = [h for h in every if h not in full]
    return None if every and not hosts else hosts


def has_room(view: WorldView, object_type: str, receptacle_type: str, excluded: Iterable[str] = (),
             full: Iterable[str] = ()) -> bool:
    """Whether some object of `object_type` has a free, stable spot in some `receptacle_type` now
    (doors counted as open), other than the `full` ones (a put found no room there). Slices that do
    not exist yet are stood in for by their whole."""
    state = view.state.without(set(excluded))
    objs = state.of_type(object_type) or state.of_type(parent_type(object_type) or "")
    hosts = _hosts(state, receptacle_type, full)
    if hosts is None:
        return False
    if not objs or not hosts:
        return True
    rng = np.random.default_rng(SPOT_SEED)
    return any(not isinstance(view.free_spot(o, h, rng, assume_open=True), Failure)
               for o in objs for h in hosts if o != h)


def has_room_for_two(view: WorldView, object_type: str, receptacle_type: str, excluded: Iterable[str] = (),
                     full: Iterable[str] = ()) -> bool:
    """Whether two different objects of `object_type` both have a free, stable spot in one
    `receptacle_type` other than the `full` ones (the second beside the first), doors counted as open.
    Two slices that do not exist yet fit where their whole does: they are pieces of it."""
    state = view.state.without(set(excluded))
    objs = state.of_type(object_type)
    hosts = _hosts(state, receptacle_type, full)
    if hosts is None:
        return False
    if not hosts:
        return True
    if not objs and state.of_type(parent_type(object_type) or ""):
        return has_room(view, object_type, receptacle_type, excluded, full)
    rng = np.random.default_rng(SPOT_SEED)
    find = view.free_spot
    for h in hosts:
        for i, a in enumerate(objs):
            first = find(a, h, rng, assume_open=True)
            if isinstance(first, Failure):
                continue
            if any(not isinstance(find(b, h, rng, assume_open=True, also=((a, first),)), Failure)
                   for b in objs[i + 1:] if b != h):
                return True
    return False


def physically_feasible(view: WorldView, params: PddlParams, excluded: Iterable[str] = (), two: bool = False,
                        full: Iterable[str] = ()) -> bool:
    """The task's object (or its movable receptacle) has room in the target receptacle (`two` of them,
    for pick_two_obj_and_place), and the object has room in its movable receptacle; receptacles a put
    already found `full` do not count."""
    return _RoomChecks(view, excluded, full).feasible(params, two)


class _RoomChecks:
    """`has_room` and `has_room_for_two` in one world state, each answer computed once: each check draws
    from its own fresh stream (`SPOT_SEED`) and moves nothing, so an answer depends on its arguments alone,
    and many candidate tasks ask the same (object type, receptacle type) question."""

    def __init__(self, view: WorldView, excluded: Iterable[str], full: Iterable[str]):
        self.view, self.excluded, self.full = view, frozenset(excluded), frozenset(full)
        self._one: dict[tuple[str, str], bool] = {}
        self._two: dict[tuple[str, str], bool] = {}

    def room(self, object_type: str, receptacle_type: str) -> bool:
        key = (object_type, receptacle_type)
        if key not in self._one:
            self._one[key] = has_room(self.view, object_type, receptacle_type, self.excluded, self.full)
        return self._one[key]

    def room_for_two(self, object_type: str, receptacle_type: str) -> bool:
        key = (object_type, receptacle_type)
        if key not in self._two:
            self._two[key] = has_room_for_two(self.view, object_type, receptacle_type, self.excluded, self.full)
        return self._two[key]

    def feasible(self, params: PddlParams, two: bool) -> bool:
        """`physically_feasible(view, params, excluded, two, full)`."""
        obj = params.object_target + ("Sliced" if params.object_sliced else "")
        inner = params.mrecep_target or obj
        if params.parent_target and not self.room(inner, params.parent_target):
            return False
        if two and params.parent_target and not self.room_for_two(inner, params.parent_target):
            return False
        return not (params.mrecep_target and not self.room(obj, params.mrecep_target))


def unseeable(view: WorldView) -> set[str]:
    """Objects to interact with that no sight line from a reachable pose meets (for one in a closed
    container, the container is what must be seen): tasks leave them out, as ALFRED's generator drops
    what its expert cannot reach."""
    return view.unseeable()


def draw_task(scene: Scene, view: WorldView, task_type: str, rng: np.random.Generator,
              excluded: Iterable[str] = (), full: Iterable[str] = (),
              keep: Callable[[PddlParams], bool] | None = None) -> TaskInstance:
    """A feasible task of `task_type` that the world can physically support, leaving out objects no
    one can see and `excluded` ones (the oracle found no pose to see them), and putting nothing in the
    `full` receptacles (a put found no room there); `keep` filters the parameters further (e.g.
    `tasks.rooms_apart`: object and receptacle in different rooms of a house). Raises TaskSamplingError
    when there is none."""
    excluded = set(excluded) | unseeable(view)
    checks = _RoomChecks(view, excluded, full)
    two = task_type == "pick_two_obj_and_place"

    def fits(p: PddlParams) -> bool:
        return (keep is None or keep(p)) and checks.feasible(p, two)

    return sample_task(scene, view.state.without(excluded), task_type, rng, keep=fits)


def distinct_tasks(scene: Scene, view: WorldView, task_type: str) -> list[PddlParams]:
    """Every parameter set `draw_task` (without `excluded`, `full` or `keep`) can return in this world, in
    the sampler's sorted order: how many different tasks of the type the layout holds.

    Raises:
        TaskSamplingError: none is feasible.
    """
    from luminous_sim.tasks.errors import TaskSamplingError
    from luminous_sim.tasks.sample import feasible_params

    excluded = unseeable(view)
    checks = _RoomChecks(view, excluded, ())
    two = task_type == "pick_two_obj_and_place"
    found = [p for p in feasible_params(scene, view.state.without(excluded), task_type) if checks.feasible(p, two)]
    if not found:
        raise TaskSamplingError(f"no {task_type} task in this layout passes the physical checks")
    return found
