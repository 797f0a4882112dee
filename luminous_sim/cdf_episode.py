"""A CDF's own task end to end: the scene generated from the CDF, its task section (goal, initial state,
agent start) as the task, solved by the oracle or by following its `execution` script, evaluated and
written like the demo's episode (`luminous run`)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from luminous_sim.cdf import ChallengeDefinition, load
from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.episode import EpisodeResult, run_task
from luminous_sim.errors import CDFError, InfeasibleSceneError, PlanningError
from luminous_sim.rooms import RoomShell
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskError, TaskInstance, names_from_scene, task_from_cdf


@dataclass(frozen=True)
class CdfEpisode:
    """What `run_cdf` did: the episode's result, the scene it ran in and the task it solved."""

    result: EpisodeResult
    scene: Scene
    task: TaskInstance
    scripted: bool
    """Whether the CDF's `execution` script was followed (else the oracle planned)."""


def run_cdf(path: Path | str, seed: int = 0, out_dir: Path | None = None, room: str | RoomShell | None = None,
            record_frames: bool = True, follow_script: bool = True) -> CdfEpisode:
    """Generate the scene a CDF file describes and run its own task in it.

    Args:
        path: the CDF file (YAML or JSON) with a `task` section.
        seed: the scene's seed (and the instructions' wording).
        out_dir: where to write trajectory.json, frames/, video.mp4, top_down.png, instructions.txt.
        room: a room-library name or a room shell to use instead of the CDF's own room choice.
        record_frames: render a frame after each action.
        follow_script: follow the CDF's `execution` script when it has one; False lets the oracle plan.

    Raises:
        CDFError: bad input, the message naming the file and the field: a malformed CDF, no task section,
            a room of a type the CDF does not allow, an agent start outside the room, a goal, initial state
            or script naming objects the scene does not have, an initial state the scene does not meet.
        InfeasibleSceneError: no layout satisfies the CDF (the message names the file).
    """
    return run_document(load(path), str(path), seed, out_dir, room, record_frames, follow_script)


def run_document(doc: ChallengeDefinition, source: str, seed: int = 0, out_dir: Path | None = None,
                 room: str | RoomShell | None = None, record_frames: bool = True,
                 follow_script: bool = True) -> CdfEpisode:
    """`run_cdf` for a CDF already in memory (e.g. one parsed from an ALFRED trajectory).

    Args:
        doc: the challenge definition, with a `task` section.
        source: where it came from, named in error messages.
        seed, out_dir, room, record_frames, follow_script: as for `run_cdf`.

    Raises:
        CDFError, InfeasibleSceneError: as for `run_cdf`.
    """
    from luminous_sim.cssg import generate, start_outside

    if doc.task is None:
        raise CDFValidationError(source, [Issue("task", "the CDF has no task section; expected task.goal "
                                                "(and optionally task.initial, task.agent, execution)")])
    if doc.scene.house is not None:
        scene = _house_scene(doc, room, seed, source)
    else:
        shell = _room(doc, room, seed, source)
        _check_start(doc, shell, source)
        try:
            scene = generate(doc, seed=seed, room=shell).scene
        except InfeasibleSceneError as exc:
            raise InfeasibleSceneError(f"{source}: {exc}") from None
        except CDFError as exc:  # sizes no asset meets
            raise CDFError(f"{source}: {exc}") from None
    outside = start_outside(doc, scene.room)  # a procedural room or a house is only known now
    if outside:
        raise CDFValidationError(source, [Issue("task.agent.position", outside)])
    try:
        task = task_from_cdf(doc, names_from_scene(scene), scene_seed=seed)
    except TaskError as exc:
        raise CDFValidationError(source, [Issue("task.goal", str(exc))]) from None
    script = doc.execution if follow_script else None
    try:
        result = run_task(scene, task, seed, out_dir, start=doc.task.agent, initial=doc.task.initial,
                          script=script, record_frames=record_frames)
    except TaskError as exc:  # an initial state the scene does not meet
        raise CDFValidationError(source, [Issue("task.initial", str(exc).removeprefix("task.initial: "))]) from None
    except PlanningError as exc:  # a script step that cannot even be stated in this scene
        raise CDFValidationError(source, [Issue("execution", str(exc))]) from None
    return CdfEpisode(result, scene, task, script is not None)


def _house_scene(doc: ChallengeDefinition, room: str | RoomShell | None, seed: int, source: str) -> Scene:
    """The house a house CDF describes (its floor plan drawn from the seed); a start outside the outline, when
    the CDF gives one, is refused before anything is generated."""
    from luminous_sim.cssg import generate_house

    house = doc.scene.house
    assert house is not None
    if room is not None:
        name = room if isinstance(room, str) else room.name
        raise CDFError(f"{source}: scene.house draws its own rooms; expected no --room (room {name!r} was given)")
    agent = doc.task.agent if doc.task is not None else None
    if house.size is not None and agent is not None and agent.position is not None:
        x, y = agent.position
        w, d = house.size.width, house.size.depth
        if not (0 < x < w and 0 < y < d):
            raise CDFValidationError(source, [Issue("task.agent.position", f"({x:g}, {y:g}) is outside the house "
                                                    f"(x 0..{w:g}, y 0..{d:g} m, scene.house.size); expected a "
                                                    "start inside a room, in house coordinates")])
    try:
        return generate_house(doc, seed=seed).scene
    except InfeasibleSceneError as exc:
        raise InfeasibleSceneError(f"{source}: {exc}") from None
    except CDFError as exc:
        raise CDFError(f"{source}: {exc}") from None


def _room(doc: ChallengeDefinition, room: str | RoomShell | None, seed: int, source: str) -> RoomShell | None:
    """The room asked for, checked against the CDF's room types; None for the CDF's own choice."""
    from luminous_sim.rooms import shell_for

    if room is None:
        return None
    shell = shell_for(room, np.random.default_rng(seed)) if isinstance(room, str) else room
    if shell.room_type not in doc.scene.room_type:
        raise CDFError(f"room {shell.name} is a {shell.room_type}, but {source} (scene.room_type) asks for "
                       f"{' or '.join(doc.scene.room_type)}; pick a room of that type (`luminous rooms list`)")
    return shell


def _check_start(doc: ChallengeDefinition, shell: RoomShell | None, source: str) -> None:
    """An agent start outside the room, before any generation: the room asked for, or the CDF's named
    library room (a procedural room is checked once drawn)."""
    from luminous_sim.cssg import start_outside
    from luminous_sim.errors import RoomError
    from luminous_sim.rooms import load_room
    from luminous_sim.rooms.library import is_procedural

    name = doc.scene.room
    if shell is None and isinstance(name, str) and not is_procedural(name):
        try:
            shell = load_room(name)
        except RoomError as exc:
            raise CDFValidationError(source, [Issue("scene.room", str(exc))]) from None
    outside = start_outside(doc, shell) if shell is not None else None
    if outside:
        raise CDFValidationError(source, [Issue("task.agent.position", outside)])
