"""One draw of a split's episode in a layout: a task of the type (`planning.draw_task`) and a start on the
reachable floor, in a world ALFRED's set-up was applied to (`episodes.alfred_set_up`); the freeze
(`episodes.freeze`) keeps the draws the oracle solves."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from luminous_sim.benchmark.counts import Layout
from luminous_sim.benchmark.key import episode_key
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskInstance
from luminous_sim.world import AgentPose, World

START_HORIZON = 30
"""The agent starts looking 30 degrees down, as in ALFRED."""


@lru_cache(maxsize=8)
def layout_scene(floor_plan: str, room_type: str, layout_seed: int) -> Scene:
    """A split layout: CSSG's default furnishing of `room_type` in the ALFRED structure `floor_plan`.

    Raises:
        InfeasibleSceneError: CSSG found no valid layout.
    """
    from luminous_sim.cssg import empty_cdf, generate
    from luminous_sim.rooms import load_room

    return generate(empty_cdf(room_type), seed=layout_seed, room=load_room(floor_plan)).scene


def scene_of(layout: Layout) -> Scene:
    """`layout_scene` of a `Layout`."""
    return layout_scene(layout.floor_plan, layout.room_type, layout.layout_seed)


def draw_seed(split_code: int, task_type_index: int, layout: Layout, draw: int) -> int:
    """The seed of draw `draw` of a task type in a layout."""
    number = int(layout.floor_plan[len("FloorPlan"):])
    words = [split_code, 100 + task_type_index, number, layout.layout, draw]
    return int(np.random.SeedSequence(words).generate_state(1, dtype=np.uint32)[0])


@dataclass(frozen=True)
class Draw:
    """A drawn episode: its task, start and initial state (the objects made dirty), and its key."""

    task: TaskInstance
    start: AgentPose
    dirty: tuple[str, ...]
    key: str


def random_start(world: World, rng: np.random.Generator) -> AgentPose:
    """A start drawn from `rng`: a reachable floor point, a quarter-turn heading, ALFRED's 30 degree horizon."""
    points = world.nav.points()
    x, y = (float(v) for v in points[int(rng.integers(len(points)))])
    return AgentPose(round(x, 4), round(y, 4), 90 * int(rng.integers(4)), START_HORIZON)


def draw(scene: Scene, world: World, task_type: str, seed: int, dirty: tuple[str, ...]) -> Draw:
    """The episode a seed draws in a world of `scene` set up for `task_type` (the world is not changed).

    Raises:
        TaskSamplingError: no task of the type fits the layout.
    """
    from luminous_sim.planning import draw_task

    rng = np.random.default_rng(seed)
    task = draw_task(scene, world.view(), task_type, rng)
    start = random_start(world, rng)
    return Draw(task, start, dirty, episode_key(scene, task_type, task.params.to_json(), start, dirty))
