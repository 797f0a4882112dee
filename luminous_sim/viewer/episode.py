"""An expert episode folder read back for playback (`luminous demo`'s `episode/`, `luminous run`'s output):
trajectory.json (the start pose and the low-level actions), frames/ (what the agent saw) and the
instructions. Pure: the agent's path is replayed from the actions, as `episode.poses_along` does."""

from __future__ import annotations

import json
import math
import os
import stat
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any, Final

from luminous_sim.data.manifest import plain_name
from luminous_sim.errors import LuminousError, mode_kind, read_file_bytes
from luminous_sim.fileio import one_line, shown
from luminous_sim.limits import (
    MAX_EPISODE_ACTIONS,
    MAX_FRAME_BYTES,
    MAX_FRAME_PIXELS,
    MAX_INPUT_BYTES,
    MAX_LAYOUT_COORDINATE_M,
)
from luminous_sim.scene import Scene
from luminous_sim.world.agent import HORIZON_MAX, HORIZON_MIN, AgentPose

MAX_TEXT_CHARS: Final = 10_000
"""Longest instruction, task description, task type or action name a trajectory may give."""


class ViewerError(LuminousError):
    """Something the viewer cannot show: no scene or no episode where one was named, or a malformed file."""


@dataclass(frozen=True)
class EpisodeStep:
    """The agent after `index` low-level actions (step 0: the start)."""

    index: int
    action: str
    """The action that led here ("start" for step 0)."""
    pose: AgentPose
    frame: Path | None
    """The agent's view after this step (a PNG), when the folder has it."""
    high_idx: int
    """Which high-level step (and instruction) this action belongs to."""
    instruction: str
    """That high-level step's instruction ("" when the episode has none)."""


@dataclass(frozen=True)
class Episode:
    """A whole episode for playback."""

    folder: Path
    task_desc: str
    task_type: str
    success: bool
    steps: tuple[EpisodeStep, ...]

    def path(self) -> list[tuple[float, float]]:
        """The agent's positions, one per step (repeats where it turned or looked)."""
        return [(s.pose.x, s.pose.y) for s in self.steps]


def _read(path: Path) -> dict[str, Any]:
    if not os.path.lexists(path):
        raise ViewerError(f"{path.parent}: no trajectory.json; expected an episode folder written by "
                          "`luminous demo` (its episode/) or `luminous run`")
    raw = read_file_bytes(path, MAX_INPUT_BYTES, "an episode's trajectory.json (luminous_sim.limits.MAX_INPUT_BYTES)",
                          ViewerError, follow_links=True)
    try:
        data = json.loads(raw)
    except RecursionError:
        raise ViewerError(f"{path}: cannot read it as JSON (nested too deeply)") from None
    except ValueError as exc:
        raise ViewerError(f"{path}: cannot read it as JSON ({exc})") from None
    if not isinstance(data, dict):
        raise ViewerError(f"{path}: expected a JSON object")
    return data


_short = partial(shown, limit=60)

def _whole(value: Any) -> int | None:
    """`value` as a whole number (an int, or a float without a fraction), else None (bools, NaN, inf, text)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return None
    if isinstance(value, float) and not (math.isfinite(value) and value.is_integer()):
        return None
    return int(value)


def _start(path: Path, data: dict[str, Any]) -> AgentPose:
    init = data.get("init_action")
    if not isinstance(init, dict) or not all(k in init for k in ("x", "z", "rotation", "horizon")):
        raise ViewerError(f"{path}: init_action: expected TeleportFull's x, z, rotation and horizon")
    for key in ("x", "z"):
        v = init[key]
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v) \
                or abs(v) > MAX_LAYOUT_COORDINATE_M:
            raise ViewerError(f"{path}: init_action.{key}: expected a finite number of metres within "
                              f"+-{MAX_LAYOUT_COORDINATE_M:g}, got {_short(v)}")
    rotation = _whole(init["rotation"])
    if rotation is None or rotation % 90 != 0 or abs(rotation) > 3600:
        raise ViewerError(f"{path}: init_action.rotation: expected 0, 90, 180 or 270 (degrees), got "
                          f"{_short(init['rotation'])}")
    horizon = _whole(init["horizon"])
    if horizon is None or not HORIZON_MIN <= horizon <= HORIZON_MAX:
        raise ViewerError(f"{path}: init_action.horizon: expected a whole number of degrees in {HORIZON_MIN}.."
                          f"{HORIZON_MAX}, got {_short(init['horizon'])}")
    return AgentPose(float(init["x"]), float(init["z"]), rotation % 360, horizon)


def _frame(path: Path) -> Path | None:
    """`path` if it is a frame to show: a regular file (not a link) within MAX_FRAME_BYTES that PIL reads as an
    image of at most MAX_FRAME_PIXELS; None when there is no file; ViewerError when it is not a frame."""
    try:
        st = os.lstat(path)
    except OSError:
        return None
    if not stat.S_ISREG(st.st_mode):
        raise ViewerError(f"{path}: {'a symbolic link' if stat.S_ISLNK(st.st_mode) else mode_kind(st.st_mode)}; "
                          "expected a frame image")
    if st.st_size > MAX_FRAME_BYTES:
        raise ViewerError(f"{path}: {st.st_size} bytes; a frame may hold at most {MAX_FRAME_BYTES} "
                          "(luminous_sim.limits.MAX_FRAME_BYTES)")
    from PIL import Image

    try:
        with Image.open(path) as im:
            width, height = im.size
    except (OSError, ValueError, Image.DecompressionBombError) as exc:
        raise ViewerError(f"{path}: not an image ({one_line(str(exc), 120)})") from None
    if width * height > MAX_FRAME_PIXELS:
        raise ViewerError(f"{path}: {width}x{height} pixels; a frame may hold at most {MAX_FRAME_PIXELS} "
                          "(luminous_sim.limits.MAX_FRAME_PIXELS)")
    return path


def _frames(path: Path, folder: Path, data: dict[str, Any], actions: int) -> list[Path | None]:
    """The frame after each step: `images` lists the start frame and one per action (ALFRED's layout,
    where an image's `low_idx` is the action it follows); without it, frames/ in name order. Every name is a
    plain file name inside frames/ (checked), and every frame a regular file that reads as an image."""
    names: list[str] = []
    images = data.get("images")
    if images is not None:
        if not isinstance(images, list) or len(images) > MAX_EPISODE_ACTIONS + 1:
            raise ViewerError(f"{path}: images: expected a list of at most {MAX_EPISODE_ACTIONS + 1} images")
        for i, image in enumerate(images):
            name = image.get("image_name") if isinstance(image, dict) else None
            if not isinstance(name, str) or not plain_name(name):
                raise ViewerError(f"{path}: images[{i}].image_name: expected a file name in frames/ (no folder "
                                  f"part), got {_short(name)}")
            names.append(name)
    if not images and (folder / "frames").is_dir() and not (folder / "frames").is_symlink():
        names = sorted(p.name for p in (folder / "frames").glob("*.png"))[:actions + 1]
    return [_frame(folder / "frames" / names[k]) if k < len(names) else None for k in range(actions + 1)]


def _texts(path: Path, data: dict[str, Any], key: str) -> list[str]:
    values = data.get(key)
    if values is None:
        return []
    if not isinstance(values, list) or len(values) > MAX_EPISODE_ACTIONS \
            or not all(isinstance(v, str) and len(v) <= MAX_TEXT_CHARS for v in values):
        raise ViewerError(f"{path}: {key}: expected a list of at most {MAX_EPISODE_ACTIONS} texts of at most "
                          f"{MAX_TEXT_CHARS} characters, got {_short(values)}")
    return values


def _text(path: Path, value: Any, key: str) -> str:
    if value is None:
        return ""
    if not isinstance(value, str) or len(value) > MAX_TEXT_CHARS:
        raise ViewerError(f"{path}: {key}: expected a text of at most {MAX_TEXT_CHARS} characters, got "
                          f"{_short(value)}")
    return value


def check_scene_of(path: Path, data: dict[str, Any], scene: Scene) -> None:
    """Refuse a trajectory played in another scene than `scene`.

    The rule: a trajectory that records `scene_key` (what `luminous demo` and `luminous run` write: the scene's
    content key, `Scene.content_key`) belongs to the scene of that key and no other. One written before keys
    were recorded names only its room (`scene`, the room's name), which must be the scene's room; one that
    records neither is refused, as nothing ties it to any scene.

    Raises:
        ViewerError: naming the trajectory, what it records and what the scene is.
    """
    key, room = data.get("scene_key"), data.get("scene")
    if key is not None:
        if not isinstance(key, str) or key != scene.content_key():
            raise ViewerError(f"{path}: scene_key {_short(key)} is not the scene's ({scene.content_key()}); the "
                              "episode was played in another scene (give the scene folder it was played in)")
        return
    if room is not None:
        if room != scene.room.name:
            raise ViewerError(f"{path}: scene {_short(room)} is not the scene's room ({scene.room.name!r}); the "
                              "episode was played in another scene (give the scene folder it was played in)")
        return
    raise ViewerError(f"{path}: records no scene (scene_key); expected an episode folder written by `luminous "
                      "demo` or `luminous run`, played in the scene given")


def load_episode(folder: Path | str, scene: Scene | None = None) -> Episode:
    """Read an episode folder: the start pose and each low-level action replayed into the agent's poses,
    the frame and the instruction of each step. Every field is checked (`limits.MAX_EPISODE_ACTIONS`,
    `MAX_FRAME_BYTES`, `MAX_FRAME_PIXELS`); with `scene`, the episode must have been played in it
    (`check_scene_of`).

    Raises:
        ViewerError: no trajectory.json there, a field of the wrong kind or out of range (named with the file),
            a frame that is not an image, or (with `scene`) an episode of another scene.
    """
    folder = Path(folder)
    path = folder / "trajectory.json"
    data = _read(path)
    if scene is not None:
        check_scene_of(path, data, scene)
    plan = data.get("plan")
    low = plan.get("low_actions") if isinstance(plan, dict) else None
    if not isinstance(low, list):
        raise ViewerError(f"{path}: plan.low_actions: expected a list of actions")
    if len(low) > MAX_EPISODE_ACTIONS:
        raise ViewerError(f"{path}: plan.low_actions: {len(low)} actions; an episode may hold at most "
                          f"{MAX_EPISODE_ACTIONS} (luminous_sim.limits.MAX_EPISODE_ACTIONS)")
    high_pddl = plan.get("high_pddl") if isinstance(plan, dict) else None
    if high_pddl is not None and not isinstance(high_pddl, list):
        raise ViewerError(f"{path}: plan.high_pddl: expected a list, got {_short(high_pddl)}")
    high_descs = _texts(path, data, "high_descs")
    highs = len(high_pddl or ()) or len(high_descs) or 1
    start = pose = _start(path, data)

    def said(high_idx: int) -> str:
        return high_descs[high_idx] if 0 <= high_idx < len(high_descs) else ""

    steps: list[tuple[str, AgentPose, int]] = []
    for k, a in enumerate(low):
        where = f"{path}: plan.low_actions[{k}]"
        api = a.get("api_action") if isinstance(a, dict) else None
        name = api.get("action") if isinstance(api, dict) else None
        if not isinstance(name, str) or not 0 < len(name) <= MAX_TEXT_CHARS:
            raise ViewerError(f"{where}: expected api_action.action, an action's name")
        high_idx = _whole(a.get("high_idx", 0))
        if high_idx is None or not 0 <= high_idx < highs:
            raise ViewerError(f"{where}.high_idx: expected a whole number in 0..{highs - 1} (an index into "
                              f"plan.high_pddl or high_descs), got {_short(a.get('high_idx'))}")
        pose = pose.after(name)
        steps.append((name, pose, high_idx))
    frames = _frames(path, folder, data, len(low))
    first_high = steps[0][2] if steps else 0
    out = [EpisodeStep(0, "start", start, frames[0], first_high, said(first_high))]
    out += [EpisodeStep(k, name, p, frames[k], h, said(h)) for k, (name, p, h) in enumerate(steps, start=1)]
    task = data.get("task")
    if task is not None and not isinstance(task, dict):
        raise ViewerError(f"{path}: task: expected an object, got {_short(task)}")
    task_type = _text(path, task.get("task_type") if task else None, "task.task_type")
    success = data.get("success", False)
    if not isinstance(success, bool):
        raise ViewerError(f"{path}: success: expected true or false, got {_short(success)}")
    return Episode(folder, _text(path, data.get("task_desc"), "task_desc"), task_type, success, tuple(out))
