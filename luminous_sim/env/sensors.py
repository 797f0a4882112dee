"""The env's observations, one sensor per key (habitat-lab's sensors): a sensor says whether a config wants it,
its space, and how to read its value from the world at a step. A new observation is one class here and a line
in `SENSORS`; the env's observation space and each observation are made from the sensors a config wants."""

from __future__ import annotations

import string
from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, ClassVar

import numpy as np
from gymnasium import spaces

from luminous_sim.env.actions import ActionTable
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.goal_mask import goal_mask
from luminous_sim.states import WorldState
from luminous_sim.vocab import ALL_TYPES, abilities
from luminous_sim.world import Frame, World

INSTRUCTION_CHARSET = string.ascii_letters + string.digits + " .,;:'!?-()\n"
MAX_INSTRUCTION = 1000
"""Characters of `instruction` kept (a directive is under 100; step instructions add about 60 a step)."""
MAX_HIGH_DESCS = 4000
"""Characters of `high_descs` kept (ALFRED's longest plans have about 25 steps of under 150 characters)."""
DEPTH_FAR = 20.0
"""The camera's far plane (metres): the largest depth."""
POSE_BOUND = 1000.0


def type_index(object_type: str | None) -> int:
    """An object type as an observation: its index in `ALL_TYPES` plus one; 0 for none."""
    return ALL_TYPES.index(object_type) + 1 if object_type in ALL_TYPES else 0


def clean_text(text: str, limit: int = MAX_INSTRUCTION) -> str:
    """Text within the observation's charset and length (other characters as spaces; never empty)."""
    out = "".join(ch if ch in INSTRUCTION_CHARSET else " " for ch in text)[:limit]
    return out or "."


@dataclass
class Reading:
    """What the sensors read at one step: the world, its frame (rendered once), the episode's texts and goal
    type; `slots` is filled by the object-slot sensor (the env decodes slot actions with it)."""

    world: World
    frame: Frame
    instruction: str
    high_descs: str
    goal_type: str
    slots: list[str] = field(default_factory=list)

    @cached_property
    def state(self) -> WorldState:
        return self.world.view().state


class Sensor(ABC):
    """One observation key."""

    key: ClassVar[str]

    def __init__(self, config: EnvConfig, actions: ActionTable):
        self.config, self.actions = config, actions

    @classmethod
    def wanted(cls, config: EnvConfig, actions: ActionTable) -> bool:
        """Whether an env of this config observes it (by default: its observation flag of the same name)."""
        return bool(getattr(config.observations, cls.key))

    @abstractmethod
    def space(self) -> spaces.Space:
        """The observation's space."""

    @abstractmethod
    def read(self, reading: Reading) -> Any:
        """The observation now (a new array: the world keeps its own, and a caller may write into this one)."""


class Rgb(Sensor):
    key = "rgb"

    @classmethod
    def wanted(cls, config: EnvConfig, actions: ActionTable) -> bool:
        return True

    def space(self) -> spaces.Space:
        o = self.config.observations
        return spaces.Box(0, 255, (o.height, o.width, 3), np.uint8)

    def read(self, reading: Reading) -> np.ndarray:
        return np.array(reading.frame.rgb[..., :3], dtype=np.uint8, order="C")


class Instruction(Sensor):
    """The goal directive (with `step_instructions`, the expert plan's step instructions after it)."""

    key = "instruction"

    @classmethod
    def wanted(cls, config: EnvConfig, actions: ActionTable) -> bool:
        return True

    def space(self) -> spaces.Space:
        return spaces.Text(MAX_INSTRUCTION, min_length=1, charset=INSTRUCTION_CHARSET)

    def read(self, reading: Reading) -> str:
        return reading.instruction


class HighDescs(Sensor):
    """The step-by-step instructions, one per line (ALFRED's `high_descs`), the same every step."""

    key = "high_descs"

    def space(self) -> spaces.Space:
        return spaces.Text(MAX_HIGH_DESCS, min_length=1, charset=INSTRUCTION_CHARSET)

    def read(self, reading: Reading) -> str:
        return reading.high_descs


class Depth(Sensor):
    """Metres, (H, W, 1) float32, never NaN (the far plane for no hit)."""

    key = "depth"

    def space(self) -> spaces.Space:
        o = self.config.observations
        return spaces.Box(0.0, DEPTH_FAR, (o.height, o.width, 1), np.float32)

    def read(self, reading: Reading) -> np.ndarray:
        depth = np.nan_to_num(reading.frame.depth, nan=DEPTH_FAR, posinf=DEPTH_FAR, neginf=0.0)
        return np.clip(depth, 0.0, DEPTH_FAR).astype(np.float32)[..., None]


class Segmentation(Sensor):
    """Instance ids (PyBullet bodies), (H, W) int32, -1 for none."""

    key = "segmentation"

    def space(self) -> spaces.Space:
        o = self.config.observations
        return spaces.Box(-1, np.iinfo(np.int32).max, (o.height, o.width), np.int32)

    def read(self, reading: Reading) -> np.ndarray:
        return reading.world.instance_ids().astype(np.int32)


class InstanceTypes(Sensor):
    """Each pixel's object type (`type_index`; 0 for structure, the background and none), (H, W) int32: the
    types of the instances in this frame only, as a detector would give them."""

    key = "instance_types"

    def space(self) -> spaces.Space:
        o = self.config.observations
        return spaces.Box(0, len(ALL_TYPES), (o.height, o.width), np.int32)

    def read(self, reading: Reading) -> np.ndarray:
        ids = reading.world.instance_ids()
        state = reading.state
        lookup = np.zeros(int(ids.max(initial=-1)) + 2, np.int32)  # body id + 1 -> type index (-1: none)
        for body, oid in reading.world.body_to_object().items():
            if oid in state.objects and body + 1 < len(lookup):
                lookup[body + 1] = type_index(state.objects[oid].object_type)
        return lookup[ids + 1]


class GoalMask(Sensor):
    """(H, W, 1) uint8, 255 on the goal type's pixels (`env.goal_mask`)."""

    key = "goal_mask"

    def space(self) -> spaces.Space:
        o = self.config.observations
        return spaces.Box(0, 255, (o.height, o.width, 1), np.uint8)

    def read(self, reading: Reading) -> np.ndarray:
        return goal_mask(reading.world, reading.goal_type)


class Pose(Sensor):
    """x, y (metres), yaw and horizon (degrees)."""

    key = "pose"

    def space(self) -> spaces.Space:
        return spaces.Box(np.array([-POSE_BOUND, -POSE_BOUND, 0, -30], np.float32),
                          np.array([POSE_BOUND, POSE_BOUND, 270, 60], np.float32), dtype=np.float32)

    def read(self, reading: Reading) -> np.ndarray:
        p = reading.world.agent
        return np.array([p.x, p.y, p.rotation % 360, p.horizon], np.float32)


class Inventory(Sensor):
    """The held object's type (`type_index`; 0 for nothing)."""

    key = "inventory"

    def space(self) -> spaces.Space:
        return spaces.Discrete(len(ALL_TYPES) + 1)

    def read(self, reading: Reading) -> int:
        state = reading.state
        return type_index(state.objects[state.held].object_type if state.held else None)


def _interactable(object_type: str) -> bool:
    ab = abilities(object_type)
    return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable or ab.sliceable


class ObjectSlots(Sensor):
    """With `objects` targets, the type in each visible-object slot (`type_index`; 0 for an empty slot); fills
    `Reading.slots` with the slots' object ids."""

    key = "objects"

    @classmethod
    def wanted(cls, config: EnvConfig, actions: ActionTable) -> bool:
        return actions.slots > 0

    def space(self) -> spaces.Space:
        return spaces.MultiDiscrete(np.full(self.actions.slots, len(ALL_TYPES) + 1, np.int64))

    def read(self, reading: Reading) -> np.ndarray:
        reading.slots[:] = self.visible(reading)
        kinds = [type_index(reading.state.objects[o].object_type) for o in reading.slots]
        return np.array(kinds + [0] * (self.actions.slots - len(kinds)), np.int64)

    def visible(self, reading: Reading) -> list[str]:
        """Objects in view and within reach that an interaction applies to, the held one aside, most pixels
        first (ties by id), as many as there are slots."""
        state = reading.state
        seen = [(-n, o) for o, n in reading.world.visible_objects().items()
                if o in state.objects and o != state.held and _interactable(state.objects[o].object_type)]
        return [o for _, o in sorted(seen)[: self.actions.slots]]


SENSORS: tuple[type[Sensor], ...] = (Rgb, Instruction, HighDescs, Depth, Segmentation, InstanceTypes, GoalMask, Pose,
                                     Inventory, ObjectSlots)
"""Every sensor, in the order of an observation's keys."""


def sensors_for(config: EnvConfig, actions: ActionTable) -> list[Sensor]:
    """The sensors an env of this config observes with."""
    return [cls(config, actions) for cls in SENSORS if cls.wanted(config, actions)]
