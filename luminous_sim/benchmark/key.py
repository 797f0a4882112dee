"""`episode_key`: a digest of what an episode is (the generated scene, the task, the initial state and the
agent's start), never of the indices or seeds that produced it, so two runs that played the same episode
have the same key whatever made them, and a changed generator changes it."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Iterable, Mapping
from typing import Any

from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose

KEY_FORMAT = "luminous-episode-key/1"
KEY_HEX = 20
"""Hex digits of the sha256 kept (80 bits)."""


def start_fields(start: AgentPose) -> list[float]:
    """A start pose as the key reads it: x, y to 0.1 mm, rotation and horizon in whole degrees."""
    return [round(float(start.x), 4) + 0.0, round(float(start.y), 4) + 0.0, int(start.rotation) % 360,
            int(start.horizon)]


def episode_key(scene: Scene | Mapping[str, Any], task_type: str, pddl_params: Mapping[str, Any],
                start: AgentPose, dirty: Iterable[str] = ()) -> str:
    """The content key of an episode.

    Args:
        scene: the scene, or its JSON document (`json.loads(scene.to_json())`, e.g. a trial's sidecar).
        task_type: the task type.
        pddl_params: the task's parameters (`PddlParams.to_json()`, ALFRED's `pddl_params`).
        start: where the agent starts.
        dirty: the objects made dirty before the first step (the initial state ALFRED's set-up gives).
    """
    doc = json.loads(scene.to_json()) if isinstance(scene, Scene) else dict(scene)
    content = {"format": KEY_FORMAT, "scene": doc, "task_type": task_type,
               "pddl_params": dict(sorted(pddl_params.items())), "start": start_fields(start),
               "dirty": sorted(dirty)}
    text = json.dumps(content, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()[:KEY_HEX]
