"""`entry_episode`: the one definition of a split's episode. Entry `i`'s layout is made by CSSG from its seed,
its task and start are drawn again from the entry's seed in a world set up as ALFRED sets one up, and the
result's `episode_key` must equal the one frozen in the manifest: a checkout whose generator, sampler or set-up
makes anything else refuses to play it (`SplitVersionError`) instead of silently playing another benchmark."""

from __future__ import annotations

from dataclasses import dataclass

from luminous_sim.benchmark.draw import draw, fresh_world, layout_scene
from luminous_sim.benchmark.frozen import SPLIT_VERSION, BenchmarkEntry
from luminous_sim.errors import LuminousError
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskInstance
from luminous_sim.world import AgentPose


class SplitVersionError(LuminousError):
    """This checkout makes a different episode than the frozen split says (the generator changed)."""


@dataclass(frozen=True)
class BenchmarkEpisode:
    """A split entry made concrete: a world of `scene`, set up with `dirty` and the agent at `start`, is the
    episode's world; `task` is what is asked."""

    entry: BenchmarkEntry
    scene: Scene
    task: TaskInstance
    start: AgentPose
    dirty: tuple[str, ...]
    key: str


def entry_episode(entry: BenchmarkEntry) -> BenchmarkEpisode:
    """The episode of a frozen split's entry (the same on every machine).

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
    world, dirty = fresh_world(scene, entry.task_type)
    try:
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
                                "split needs a new version (python -m luminous_sim.benchmark.freeze)")
    return BenchmarkEpisode(entry, scene, drawn.task, drawn.start, drawn.dirty, drawn.key)
