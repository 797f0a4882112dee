"""An expert episode folder read back for playback (`luminous demo`'s `episode/`, `luminous run`'s output):
trajectory.json (the start pose and the low-level actions), frames/ (what the agent saw) and the
instructions. Pure: the agent's path is replayed from the actions, as `episode.poses_along` does."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError
from luminous_sim.world.agent import AgentPose


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
    if not path.is_file():
        raise ViewerError(f"{path.parent}: no trajectory.json; expected an episode folder written by "
                          "`luminous demo` (its episode/) or `luminous run`")
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise ViewerError(f"{path}: cannot read it as JSON ({exc})") from None
    if not isinstance(data, dict):
        raise ViewerError(f"{path}: expected a JSON object")
    return data


def _start(path: Path, data: dict[str, Any]) -> AgentPose:
    init = data.get("init_action")
    problem = ViewerError(f"{path}: init_action: expected TeleportFull's x, z, rotation and horizon")
    if not isinstance(init, dict):
        raise problem
    try:
        return AgentPose(float(init["x"]), float(init["z"]), int(init["rotation"]) % 360, int(init["horizon"]))
    except (KeyError, TypeError, ValueError):
        raise problem from None


def _frames(folder: Path, data: dict[str, Any], actions: int) -> list[Path | None]:
    """The frame after each step: `images` lists the start frame and one per action (ALFRED's layout,
    where an image's `low_idx` is the action it follows); without it, frames/ in name order."""
    names: list[str] = []
    images = data.get("images")
    if isinstance(images, list) and images and all(isinstance(i, dict) and "image_name" in i for i in images):
        names = [str(i["image_name"]) for i in images]
    elif (folder / "frames").is_dir():
        names = sorted(p.name for p in (folder / "frames").glob("*.png"))
    out: list[Path | None] = []
    for k in range(actions + 1):
        path = folder / "frames" / names[k] if k < len(names) else None
        out.append(path if path is not None and path.is_file() else None)
    return out


def load_episode(folder: Path | str) -> Episode:
    """Read an episode folder: the start pose and each low-level action replayed into the agent's poses,
    the frame and the instruction of each step.

    Raises:
        ViewerError: no trajectory.json there, or one without a start pose or low-level actions.
    """
    folder = Path(folder)
    path = folder / "trajectory.json"
    data = _read(path)
    plan = data.get("plan")
    low = plan.get("low_actions") if isinstance(plan, dict) else None
    if not isinstance(low, list):
        raise ViewerError(f"{path}: plan.low_actions: expected a list of actions")
    high_descs = [str(d) for d in data.get("high_descs") or []]
    frames = _frames(folder, data, len(low))
    pose = _start(path, data)

    def said(high_idx: int) -> str:
        return high_descs[high_idx] if 0 <= high_idx < len(high_descs) else ""

    first_high = int(low[0].get("high_idx", 0)) if low else 0
    steps = [EpisodeStep(0, "start", pose, frames[0], first_high, said(first_high))]
    for k, a in enumerate(low, start=1):
        try:
            name = str(a["api_action"]["action"])
        except (KeyError, TypeError):
            raise ViewerError(f"{path}: plan.low_actions[{k - 1}]: expected api_action.action") from None
        pose = pose.after(name)
        high_idx = int(a.get("high_idx", 0))
        steps.append(EpisodeStep(k, name, pose, frames[k], high_idx, said(high_idx)))
    task = data.get("task")
    task_type = str(task.get("task_type", "")) if isinstance(task, dict) else ""
    return Episode(folder, str(data.get("task_desc", "")), task_type, bool(data.get("success", False)), tuple(steps))
