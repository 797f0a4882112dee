"""Episodes from CDF files (the env's `EnvConfig.cdf`, or `reset(options={"cdf": path})`): the scene is generated
from the CDF (`cssg.generate(doc, seed)`); if the CDF has a task section, that is the episode's goal
(`tasks.task_from_cdf`), with its initial object states set in the scene and its agent start; otherwise a
task of the drawing's types is drawn in the scene, as for a scene generated on the fly.

The scene's seed is drawn from the reset's rng, or fixed by `reset(options={"scene_seed": s})`, in which
case the same CDF gives the same scene (generated once, kept) and the env reuses its worlds. As for every
drawn episode, one the expert does not solve is replaced (`Drawing.verify_expert`): another scene seed, or
another task; the count is the spec's `redraws`.

What `luminous run` does with a CDF (`cdf_episode.run_cdf`, layer L5) is followed here for the parts an
environment needs: the initial states and their check (`tasks.scene_with_initial`, `tasks.check_initial`)
and the agent start (`start_pose`, which `luminous run` uses too).
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache
from pathlib import Path

import numpy as np

from luminous_sim.cdf import AgentPoseSpec, ChallengeDefinition
from luminous_sim.episodes.generated import Drawing, proved
from luminous_sim.episodes.goals import Goal, TaskGoal
from luminous_sim.episodes.initial_state import WorldSource
from luminous_sim.episodes.spec import EpisodeSpec
from luminous_sim.errors import CDFError, InfeasibleSceneError, LuminousError
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskError, TaskSamplingError, check_initial, scene_with_initial
from luminous_sim.world import AgentPose, World


@lru_cache(maxsize=32)
def _load(path: str, mtime_ns: int) -> ChallengeDefinition:
    from luminous_sim import cdf

    return cdf.load(path)


def load_cdf(path: str) -> ChallengeDefinition:
    """The validated CDF (read again when the file changes).

    Raises:
        CDFValidationError: anything wrong, the message naming the file and the key.
    """
    p = Path(path).resolve()
    return _load(str(p), p.stat().st_mtime_ns)


@lru_cache(maxsize=8)
def _generated(path: str, mtime_ns: int, seed: int) -> Scene:
    from luminous_sim.cssg import generate

    try:
        return generate(_load(path, mtime_ns), seed=seed).scene
    except InfeasibleSceneError as exc:
        raise InfeasibleSceneError(f"{path}: {exc}") from None
    except CDFError as exc:  # sizes no asset meets
        raise CDFError(f"{path}: {exc}") from None


def cdf_scene(path: str, seed: int) -> Scene:
    """The scene CSSG generates from the CDF with this seed (kept: the same file and seed, the same object)."""
    p = Path(path).resolve()
    return _generated(str(p), p.stat().st_mtime_ns, seed)


def start_pose(world: World, spec: AgentPoseSpec | None) -> AgentPose | None:
    """The CDF's agent start (`task.agent`): the reachable point nearest its position, its rotation and
    horizon (unset parts from the default start); None when the CDF gives none."""
    if spec is None:
        return None
    pose = world.agent
    x, y = pose.x, pose.y
    if spec.position is not None:
        pts = world.nav.points()
        x, y = (float(v) for v in pts[int(np.argmin(np.linalg.norm(pts - np.array(spec.position), axis=1)))])
    return AgentPose(x, y, pose.rotation if spec.rotation is None else spec.rotation,
                     pose.horizon if spec.horizon is None else spec.horizon)


def draw_from_cdf(drawing: Drawing, paths: Sequence[str], rng: np.random.Generator, worlds: WorldSource,
                  scene_seed: int | None = None) -> tuple[EpisodeSpec, World]:
    """An episode in a scene generated from one of the CDF files (drawn uniformly), and its world.

    Raises:
        CDFValidationError: a CDF that is malformed, or whose task names objects the scene lacks.
        LuminousError: a task.initial that does not hold, an agent start off the floor, or no attempt gave
            an episode (the message lists why).
    """
    from luminous_sim.cssg import start_outside
    from luminous_sim.tasks import names_from_scene, task_from_cdf

    why: list[str] = []
    for _ in range(drawing.attempts):
        path = paths[int(rng.integers(len(paths)))]
        doc = load_cdf(path)
        seed = scene_seed if scene_seed is not None else int(rng.integers(2**31))
        try:
            scene = cdf_scene(path, seed)
        except InfeasibleSceneError as exc:
            why.append(str(exc))
            if scene_seed is not None:
                break
            continue
        start = None
        if doc.task is not None:
            outside = start_outside(doc, scene.room)
            if outside:
                raise LuminousError(f"{path}: task.agent.position: {outside}")
            names = names_from_scene(scene)
            try:
                goal: Goal = TaskGoal(task_from_cdf(doc, names, scene_seed=seed))
            except TaskError as exc:
                raise LuminousError(f"{path}: task.goal: {exc}") from None
            try:
                scene = scene_with_initial(scene, doc.task.initial, names)
            except TaskError as exc:
                raise LuminousError(f"{path}: {exc}") from None
            world = worlds.get(scene)
            try:
                check_initial(world.view().state, doc.task.initial, names)
            except TaskError as exc:
                worlds.put(world)
                raise LuminousError(f"{path}: {exc}") from None
            start = start_pose(world, doc.task.agent)
        else:
            world = worlds.get(scene)
            try:
                task_type = drawing.task_types[int(rng.integers(len(drawing.task_types)))]
                goal = drawing.kind(task_type).draw_goal(world, scene, rng)
            except TaskSamplingError as exc:
                worlds.put(world)
                why.append(f"{path} seed {seed}: {exc}")
                continue
        dirty = drawing.set_up(world, goal.task_type)
        if start is not None:
            world.set_start(start)
        spec = proved(EpisodeSpec(scene, goal, dirty, start=start, redraws=len(why)), worlds, drawing)
        if spec is None:
            worlds.put(world)
            why.append(f"the expert does not solve {goal.instruction!r} in {path} (seed {seed})")
            if scene_seed is not None and doc.task is not None:
                break
            continue
        return spec, world
    raise LuminousError(f"no episode from {', '.join(paths)}: " + "; ".join(why[-3:]))
