"""An env's configuration by concern, each a pydantic model that checks its own fields: what the agent observes
(`ObservationSettings`), how it acts (`ActionSettings`), what it is paid (`RewardSettings`), where episodes
come from (`SourceSettings`, with each task kind's own options in `kinds.options`) and when an episode is cut
off (`LimitSettings`). `EnvConfig` (the flat keyword arguments of `gym.make`) is made of them.

A value of the wrong type or out of its range is a one-line `LuminousError` naming the field and what was
expected (`settings_error` turns pydantic's report into it)."""

from __future__ import annotations

import math
import os
from functools import partial
from pathlib import Path
from typing import Any, Literal, get_args

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from luminous_sim.env.kinds import TASK_KINDS
from luminous_sim.env.kinds.options import check_task_options, field_bounds
from luminous_sim.env.rewards import RewardConfig
from luminous_sim.errors import LuminousError
from luminous_sim.fileio import shown
from luminous_sim.vocab import ALFRED_TASK_TYPES, ROOM_TYPES

RewardMode = Literal["dense", "sparse"]
TargetKind = Literal["points", "objects"]
Rasteriser = Literal["tinyrenderer", "compiled"]
REWARD_MODES: tuple[str, ...] = get_args(RewardMode)
TARGET_KINDS: tuple[str, ...] = get_args(TargetKind)
RASTERISERS: tuple[str, ...] = get_args(Rasteriser)

IMAGE_SIZE: tuple[int, int] = (16, 1024)
"""Least and most pixels a side (`width`, `height`). Rendering cost grows with the pixel count (see
docs/benchmarks.md for frames a second), and so do its buffers; under 16 a side, ALFRED's visibility
threshold and a grid of interaction points no longer mean anything."""
MAX_GRID = 32
"""Most interaction points a side (`grid`; a 32x32 grid is 7 x 1024 interaction actions)."""
MAX_OBJECT_SLOTS = 256
"""Most visible-object slots (`object_slots`; a generated room holds under 200 objects)."""
MAX_STEPS = 1_000_000
"""Most steps an episode may be given (`max_steps`, `max_failures`; ALFRED: 1000 and 10)."""
MAX_SCENE_ATTEMPTS = 100
"""Most scenes (or tasks) one reset tries (`scene_attempts`; each may cost a CSSG run and a plan)."""
MAX_REWARD = 1e6
"""Largest magnitude of a reward term (`reward` overrides; ALFRED's are within 5)."""
MAX_NAMES = 64
"""Most entries in `task_types` or `room_types` (an entry may repeat to weight the draw)."""
MAX_CDF_FILES = 10_000
"""Most CDF files in `cdf` (each is checked to exist when the env is made)."""


short_repr = partial(shown, limit=80)
"""A value for a one-line message (long ones cut)."""

class Settings(BaseModel):
    """One concern's settings: strict types (no 64.0 for an int, no "yes" for a bool), frozen, no unknown name."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


def _count(default: int, low: int, high: int) -> Any:
    return Field(default, ge=low, le=high)


class ObservationSettings(Settings):
    """What the agent observes: the camera, and the observations beside `rgb` and `instruction` (one sensor
    each, `env.sensors`)."""

    width: int = _count(300, *IMAGE_SIZE)
    height: int = _count(300, *IMAGE_SIZE)
    depth: bool = False
    segmentation: bool = False
    instance_types: bool = False
    goal_mask: bool = False
    pose: bool = False
    inventory: bool = False
    step_instructions: bool = False
    high_descs: bool = False
    min_visible_pixels: int = 0
    """0 scales ALFRED's 10 at 300x300 to the image size (`visible_pixels`); at most the image's pixels."""
    rasteriser: Rasteriser = "tinyrenderer"

    @model_validator(mode="after")
    def _pixels(self) -> ObservationSettings:
        most = self.width * self.height
        if not 0 <= self.min_visible_pixels <= most:
            raise ValueError(f"min_visible_pixels: expected an integer in 0..{most}, got {self.min_visible_pixels}")
        return self

    @property
    def visible_pixels(self) -> int:
        """Pixels an object needs to be visible: ALFRED's 10 at 300x300, scaled to this image's area."""
        if self.min_visible_pixels > 0:
            return self.min_visible_pixels
        return max(1, round(10 * self.width * self.height / (300 * 300)))


class ActionSettings(Settings):
    """How the agent acts: interactions on a grid of image points or on visible-object slots; the expert's next
    action in `info`."""

    targets: TargetKind = "points"
    grid: int = _count(5, 1, MAX_GRID)
    object_slots: int = _count(16, 1, MAX_OBJECT_SLOTS)
    expert_in_info: bool = False


class RewardSettings(Settings):
    """What the agent is paid (`RewardConfig.of(reward_mode, reward)`, and ALFRED's navigation reward)."""

    reward_mode: RewardMode = "dense"
    reward: dict[str, int | float] = Field(default_factory=dict)
    """Overrides of `RewardConfig` terms, by name (kept as given: `to_kwargs` gives them back unchanged)."""
    navigation_reward: bool = True

    @field_validator("reward", mode="before")
    @classmethod
    def _terms(cls, value: Any) -> Any:
        if not isinstance(value, dict) or not all(isinstance(k, str) for k in value):
            raise ValueError(f"reward: expected a table of term name -> number, got {short_repr(value)}")
        for k, v in value.items():
            if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v) or abs(v) > MAX_REWARD:
                raise ValueError(f"reward.{k}: expected a finite number within +-{MAX_REWARD:g}, got {short_repr(v)}")
        return value

    def config(self) -> RewardConfig:
        """The reward terms in force.

        Raises:
            LuminousError: an override names no term.
        """
        return RewardConfig.of(self.reward_mode, self.reward)


def _names(name: str, value: Any, most: int) -> tuple[str, ...]:
    """A list of names (strings; for `cdf`, paths too) as a tuple; ValueError naming the field otherwise."""
    if name == "cdf" and isinstance(value, str | os.PathLike):
        value = (value,)
    if not isinstance(value, list | tuple) or not all(isinstance(v, str | os.PathLike) for v in value) \
            or (name != "cdf" and not all(isinstance(v, str) for v in value)):
        raise ValueError(f"{name}: expected a list of {'paths' if name == 'cdf' else 'names'}, got {short_repr(value)}")
    if len(value) > most:
        raise ValueError(f"{name}: expected at most {most} entries, got {len(value)}")
    out = tuple(os.fspath(v) for v in value)
    if not all(isinstance(v, str) for v in out):
        raise ValueError(f"{name}: expected text paths, got {short_repr(value)}")
    return out


class SourceSettings(Settings):
    """Where episodes come from: task kinds drawn in generated rooms (of `room_types`), a frozen split, or CDF
    files; whether the expert must solve them; each kind's options (`kinds.options`)."""

    task_types: tuple[str, ...] = ALFRED_TASK_TYPES
    room_types: tuple[str, ...] = ()
    split: str = ""
    cdf: tuple[str, ...] = ()
    scene_attempts: int = _count(8, 1, MAX_SCENE_ATTEMPTS)
    verify_expert: bool = True
    task_options: dict[str, int | float] = Field(default_factory=dict)

    @field_validator("task_types", "room_types", "cdf", mode="before")
    @classmethod
    def _lists(cls, value: Any, info: Any) -> tuple[str, ...]:
        return _names(info.field_name, value, MAX_CDF_FILES if info.field_name == "cdf" else MAX_NAMES)

    @field_validator("task_options", mode="before")
    @classmethod
    def _numbers(cls, value: Any) -> Any:
        if not isinstance(value, dict) or not all(isinstance(v, int | float) and not isinstance(v, bool)
                                                  and math.isfinite(v) for v in value.values()):
            raise ValueError(f"task_options: expected a table of finite numbers, got {short_repr(value)}")
        return value

    def check(self) -> None:
        """What a field alone cannot say: known task kinds and room types, the kinds' options, a split that
        exists, CDF files that exist, not both a split and CDFs.

        Raises:
            LuminousError: one line naming the field.
        """
        bad = [t for t in self.task_types if t not in TASK_KINDS]
        if not self.task_types or bad:
            raise LuminousError(f"env config task_types: {short_repr(bad) if bad else 'empty'}; expected some of "
                                f"{', '.join(TASK_KINDS)}")
        check_task_options(self.task_types, self.task_options)
        bad = [r for r in self.room_types if r not in ROOM_TYPES]
        if bad:
            raise LuminousError(f"env config room_types: {short_repr(bad)}; expected some of {', '.join(ROOM_TYPES)}")
        if self.split:
            from luminous_sim.splits import PLUS_SPLITS  # only when asked: `import luminous_sim` stays cheap

            if self.split not in PLUS_SPLITS:
                raise LuminousError(f"env config split: {short_repr(self.split)}; expected one of "
                                    f"{', '.join(PLUS_SPLITS)}")
        if self.cdf and self.split:
            raise LuminousError("env config: give split or cdf, not both (where would the scenes come from?)")
        missing = [p for p in self.cdf if not Path(p).is_file()]
        if missing:
            raise LuminousError(f"env config cdf: {', '.join(missing[:3])}{' ...' if len(missing) > 3 else ''}: "
                                "no such CDF file")


class LimitSettings(Settings):
    """When an episode is cut off (`truncated`): ALFRED's 1000 steps and 10 failed actions by default."""

    max_steps: int = _count(1000, 1, MAX_STEPS)
    max_failures: int = _count(10, 1, MAX_STEPS)


PARTS: dict[str, type[Settings]] = {
    "observations": ObservationSettings, "actions": ActionSettings, "rewards": RewardSettings,
    "source": SourceSettings, "limits": LimitSettings,
}
"""The concerns of an env's config, by the name `EnvConfig` gives each."""
FIELD_PART: dict[str, str] = {name: part for part, model in PARTS.items() for name in model.model_fields}
"""Each flat keyword argument -> the concern it belongs to."""


def settings_error(exc: ValidationError, values: dict[str, Any]) -> LuminousError:
    """pydantic's first complaint as the one-line message an env config error is."""
    error = exc.errors()[0]
    name = str(error["loc"][0]) if error["loc"] else ""
    value = values.get(name, error.get("input"))
    kind = error["type"]
    if kind == "value_error":  # our own validators' messages, which name the field
        return LuminousError(f"env config {(error.get('ctx') or {}).get('error', error['msg'])}")
    field = PARTS[FIELD_PART[name]].model_fields[name] if name in FIELD_PART else None
    if kind in ("greater_than_equal", "less_than_equal") and field is not None:
        low, high = field_bounds(field)
        return LuminousError(f"env config {name}: expected an integer in {low}..{high}, got {short_repr(value)}")
    if kind == "literal_error" and field is not None:
        return LuminousError(f"env config {name}: {short_repr(value)}; expected one of {get_args(field.annotation)}")
    what = {"bool_type": "true or false", "int_type": "an integer", "string_type": "a string",
            "dict_type": "a table", "tuple_type": "a list"}.get(kind, error["msg"].lower())
    return LuminousError(f"env config {name}: expected {what}, got {short_repr(value)}")
