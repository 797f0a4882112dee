"""A kitchen generated once for the viewer's tests (the export tests' CDF), saved as a scene folder, and a
small episode folder in it written by hand: trajectory.json in ALFRED's layout, a frame per step, the
instructions."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.cssg import generate
from luminous_sim.scene import Scene, scene_reachable_grid

REPO = Path(__file__).resolve().parents[2]
KITCHEN = REPO / "cdf" / "examples" / "kitchen_apple_fridge.yaml"
ACTIONS = ("MoveAhead", "RotateRight", "MoveAhead", "LookDown", "MoveAhead")
HIGH_DESCS = ("Walk to the counter.", "Look at the apple.")


@pytest.fixture(scope="package")
def kitchen() -> Scene:
    return generate(cdf.load(KITCHEN), seed=0).scene


@pytest.fixture(scope="package")
def scene_dir(kitchen: Scene, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("kitchen")
    kitchen.save(out / "scene.json")
    return out


def write_episode(out: Path, start: tuple[float, float], frames: bool = True, scene: Scene | None = None) -> Path:
    """An episode folder as `luminous demo` writes one, with ACTIONS from `start` facing north (played in
    `scene`: its content key recorded; None: the room name "kitchen" only)."""
    from PIL import Image

    low = [{"api_action": {"action": a, "forceAction": True}, "discrete_action": {"action": a, "args": {}},
            "high_idx": 0 if k < 3 else 1} for k, a in enumerate(ACTIONS)]
    images = [{"high_idx": 0, "image_name": f"{0:09d}.png", "low_idx": 0}] + [
        {"high_idx": a["high_idx"], "image_name": f"{k + 1:09d}.png", "low_idx": k} for k, a in enumerate(low)]
    record = {"init_action": {"action": "TeleportFull", "x": start[0], "y": 0.9009995, "z": start[1],
                              "rotation": 0, "horizon": 30, "rotateOnTeleport": True},
              "plan": {"high_pddl": [], "low_actions": low}, "images": images, "success": True,
              "task": {"task_type": "look_at_obj_in_light"}, "task_desc": "look at the apple",
              "high_descs": list(HIGH_DESCS), "goal_conditions": [1, 1], "scene": "kitchen"}
    if scene is not None:
        record.update(scene=scene.room.name, scene_key=scene.content_key())
    out.mkdir(parents=True, exist_ok=True)
    (out / "trajectory.json").write_text(json.dumps(record))
    (out / "instructions.txt").write_text("\n".join(["look at the apple", "", *HIGH_DESCS]) + "\n")
    if frames:
        (out / "frames").mkdir(exist_ok=True)
        for k in range(len(ACTIONS) + 1):
            shade = np.full((300, 300, 3), 30 * k, dtype=np.uint8)
            Image.fromarray(shade).save(out / "frames" / f"{k:09d}.png")
    return out


@pytest.fixture(scope="package")
def episode_dir(kitchen: Scene, tmp_path_factory: pytest.TempPathFactory) -> Path:
    x, y = (float(v) for v in scene_reachable_grid(kitchen)[0])
    return write_episode(tmp_path_factory.mktemp("episode"), (x, y), scene=kitchen)
