"""`EnvConfig`: everything that defines one environment id, as plain JSON-serialisable values.

The keyword arguments of `LuminousEnv` (and so of a spec in `envs/*.toml`) are exactly this dataclass's
fields; a wrong name or type is a `LuminousError` that names the field and what was expected.
"""

from __future__ import annotations

import math
import os
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import Any

from luminous_sim.env.kinds import KIND_OPTIONS, TASK_KINDS
from luminous_sim.env.rewards import RewardConfig
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES, ROOM_TYPES

REWARD_MODES: tuple[str, ...] = ("dense", "sparse")
TARGET_KINDS: tuple[str, ...] = ("points", "objects")
RASTERISERS: tuple[str, ...] = ("tinyrenderer", "compiled")

IMAGE_SIZE: tuple[int, int] = (16, 1024)
"""Least and most pixels a side (`width`, `height`). Rendering cost grows with the pixel count (TinyRenderer:
about 44 frames/s at ALFRED's 300x300, so about 4 at 1024x1024, and its buffers grow alike); under 16 a
side, ALFRED's visibility threshold and a grid of interaction points no longer mean anything."""
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
MAX_TASK_DISTANCE = 100.0
"""Largest distance (metres) a task option may name (a success or minimum start distance): a house is under 30 m."""


@dataclass(frozen=True)
class EnvConfig:
    """One environment's definition (ALFRED's camera, limits and reward configuration by default).

    Every field is checked when the config is made (so when the env is made); a value of the wrong type or
    out of its range is a one-line `LuminousError` naming the field and what was expected. Limits (the
    module's constants): `width`, `height` 16..1024 (`IMAGE_SIZE`); `grid` 1..32 and at most the image's
    shorter side (`MAX_GRID`); `object_slots` 1..256 (`MAX_OBJECT_SLOTS`); `max_steps`, `max_failures`
    1..1,000,000 (`MAX_STEPS`); `scene_attempts` 1..100 (`MAX_SCENE_ATTEMPTS`); `min_visible_pixels`
    0..width x height; `reward` values finite, within +-1e6 (`MAX_REWARD`); `task_types`, `room_types` at
    most 64 entries (`MAX_NAMES`); `cdf` at most 10,000 files (`MAX_CDF_FILES`). Room types that cannot go
    with the task types (ALFRED's table) are refused when the env is made (`episodes.check_rooms`).

    Attributes:
        task_types: the task kinds an episode draws from (uniformly): ALFRED's types, `goto_object`,
            `pickup_object` (`luminous_sim.env.kinds.TASK_KINDS`).
        room_types: the room types scenes are generated in, each drawn task type in those of them it allows
            (ALFRED's table); empty means every room type the drawn task type allows. Every task type must
            be allowed in one of them, and every one of them must allow some task type.
        width: image width in pixels.
        height: image height in pixels.
        targets: what an interaction action targets: `points` (a k x k grid of image points) or `objects`
            (visible-object slots, listed in an `objects` observation).
        grid: k, the side of the k x k grid of image points (`points` targets).
        object_slots: the number of visible-object slots (`objects` targets).
        depth: add a `depth` observation (float32 metres).
        segmentation: add a `segmentation` observation (int32 instance index, -1 for background).
        goal_mask: add a `goal_mask` observation: (H, W, 1) uint8, 255 where an object of the goal's type shows
            (the goal's `object_type`; ALFRED's tasks: `pddl_params.object_target`'s type), else 0. A semantic
            sensor for the goal's category only: privileged perception, as ObjectNav's ground-truth
            semantics setting; a policy trained with it is evaluated with it.
        pose: add a `pose` observation (x, y metres, yaw and horizon degrees).
        inventory: add an `inventory` observation (index of the held object's type, 0 for none).
        step_instructions: follow the goal directive in `instruction` with step-by-step instructions (the
            language layer's templates over the expert's plan; needs `verify_expert`).
        high_descs: add a `high_descs` observation: the step-by-step instructions, one per line (ALFRED's
            `high_descs`: a built trial's annotation, else the templates over the expert's plan), fixed for
            the episode; needs `verify_expert`.
        max_steps: episode truncated after this many steps (ALFRED: 1000).
        max_failures: episode truncated after this many failed actions (ALFRED: 10).
        reward_mode: `dense` (ALFRED's configuration driven by the goal conditions) or `sparse`.
        reward: overrides of `RewardConfig` fields, by name.
        navigation_reward: add ALFRED's navigation reward (the expert's go-to subgoals, spec section 5.2) to
            the dense reward (needs `verify_expert`: the go-to locations are the expert's); the `-v0` ids
            were registered without it.
        expert_in_info: put the expert's next action in `info` (it costs a plan when the agent deviates).
        verify_expert: keep only episodes the oracle solves (as ALFRED's generator does); it also gives
            the expert length that ALFRED's step penalty starts after.
        scene_attempts: scenes tried before `reset` gives up on finding a task that fits.
        min_visible_pixels: pixels an object needs to count as visible; 0 scales ALFRED's 10 at 300x300
            to the image size.
        rasteriser: who draws the frames: `tinyrenderer` (PyBullet's own) or `compiled` (TinyRenderer's
            rasteriser compiled with numba: the same RGB and segmentation but for a few pixels in a million,
            depth within 1e-4 m, a 64 px step about 3.2x cheaper, about 150 MB more memory per process);
            `WorldConfig.rasteriser`. The RL ids of `envs/small.toml` and the HouseNav ids use `compiled`.
        split: play the episodes of an evaluation split (`S+`, `U+`, `U+test`; see `luminous_sim.splits`)
            instead of generating scenes on the fly: `reset(options={"index": i})` plays entry i, a plain
            `reset` an entry drawn over one round of the split; "" (the default) generates on the fly.
            `reset(options={"split": name, "index": i})` does the same for one episode of any env.
        cdf: CDF files (a path or a list) to generate each episode's scene from (one drawn uniformly per
            reset; see `luminous_sim.env.cdf_scenes`): a CDF's own task is the goal, else a task of
            `task_types` is drawn. `reset(options={"cdf": path, "scene_seed": s})` does the same for one
            episode of any env; () (the default) generates scenes on the fly.
        task_options: options of the task kinds, by name (`luminous_sim.env.kinds.KIND_OPTIONS`: `objectnav`'s
            `success_distance` and `min_start_distance` in metres, `objectnav_pickup`'s `min_start_distance`);
            each kind takes its own, the rest keep their defaults.
    """

    task_types: tuple[str, ...] = ALFRED_TASK_TYPES
    room_types: tuple[str, ...] = ()
    width: int = 300
    height: int = 300
    targets: str = "points"
    grid: int = 5
    object_slots: int = 16
    depth: bool = False
    segmentation: bool = False
    goal_mask: bool = False
    pose: bool = False
    inventory: bool = False
    step_instructions: bool = False
    high_descs: bool = False
    max_steps: int = 1000
    max_failures: int = 10
    reward_mode: str = "dense"
    reward: dict[str, float] = field(default_factory=dict)
    navigation_reward: bool = True
    expert_in_info: bool = False
    verify_expert: bool = True
    scene_attempts: int = 8
    min_visible_pixels: int = 0
    rasteriser: str = "tinyrenderer"
    split: str = ""
    cdf: tuple[str, ...] = ()
    task_options: dict[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "cdf" and isinstance(value, (str, os.PathLike)):
                object.__setattr__(self, "cdf", (os.fspath(value),))
            elif f.name in ("task_types", "room_types", "cdf"):
                object.__setattr__(self, f.name, _names(f.name, value, MAX_CDF_FILES if f.name == "cdf" else MAX_NAMES))
            elif f.name == "reward":
                _check_reward(value)
            elif f.name == "task_options":
                if not isinstance(value, dict) or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                                          and math.isfinite(v) for v in value.values()):
                    raise LuminousError(f"env config task_options: expected a table of finite numbers, got "
                                        f"{short_repr(value)}")
            elif f.type == "bool" and not isinstance(value, bool):
                raise LuminousError(f"env config {f.name}: expected true or false, got {short_repr(value)}")
            elif f.type == "int" and (isinstance(value, bool) or not isinstance(value, int)):
                raise LuminousError(f"env config {f.name}: expected an integer, got {short_repr(value)}")
            elif f.type == "str" and not isinstance(value, str):
                raise LuminousError(f"env config {f.name}: expected a string, got {short_repr(value)}")
        self._check_values()

    def _check_values(self) -> None:
        bad = [t for t in self.task_types if t not in TASK_KINDS]
        if not self.task_types or bad:
            raise LuminousError(f"env config task_types: {short_repr(bad) if bad else 'empty'}; expected some of "
                                f"{', '.join(TASK_KINDS)}")
        known = {o for t in self.task_types for o in KIND_OPTIONS.get(t, ())}
        bad = sorted(set(self.task_options) - known)
        if bad:
            raise LuminousError(f"env config task_options: {bad}; the task types {', '.join(self.task_types)} take "
                                f"{', '.join(sorted(known)) or 'none'}")
        if any(not 0 <= v <= MAX_TASK_DISTANCE for v in self.task_options.values()):
            raise LuminousError(f"env config task_options: expected distances in 0..{MAX_TASK_DISTANCE:g} m, got "
                                f"{short_repr(self.task_options)}")
        bad = [r for r in self.room_types if r not in ROOM_TYPES]
        if bad:
            raise LuminousError(f"env config room_types: {short_repr(bad)}; expected some of {', '.join(ROOM_TYPES)}")
        if self.rasteriser not in RASTERISERS:
            raise LuminousError(f"env config rasteriser: {short_repr(self.rasteriser)}; expected one of {RASTERISERS}")
        if self.targets not in TARGET_KINDS:
            raise LuminousError(f"env config targets: {short_repr(self.targets)}; expected one of {TARGET_KINDS}")
        if self.reward_mode not in REWARD_MODES:
            raise LuminousError(f"env config reward_mode: {short_repr(self.reward_mode)}; expected one of "
                                f"{REWARD_MODES}")
        RewardConfig.of(self.reward_mode, self.reward)  # unknown terms
        limits = {"width": IMAGE_SIZE, "height": IMAGE_SIZE, "grid": (1, MAX_GRID),
                  "object_slots": (1, MAX_OBJECT_SLOTS), "max_steps": (1, MAX_STEPS), "max_failures": (1, MAX_STEPS),
                  "scene_attempts": (1, MAX_SCENE_ATTEMPTS),
                  "min_visible_pixels": (0, self.width * self.height)}
        for name, (low, high) in limits.items():
            value = getattr(self, name)
            if not low <= value <= high:
                raise LuminousError(f"env config {name}: expected an integer in {low}..{high}, got {value}")
        if self.step_instructions and not self.verify_expert:
            raise LuminousError("env config step_instructions: needs verify_expert (they describe the expert's plan)")
        if self.high_descs and not self.verify_expert:
            raise LuminousError("env config high_descs: needs verify_expert (they describe the expert's plan)")
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
        if self.grid > min(self.width, self.height):
            raise LuminousError(f"env config grid: {self.grid} points a side do not fit a {self.width}x{self.height}"
                                " image")

    @classmethod
    def from_kwargs(cls, kwargs: dict[str, Any]) -> EnvConfig:
        """The config of `LuminousEnv(**kwargs)`; an unknown name is a LuminousError listing the known ones."""
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(kwargs) - known)
        if unknown:
            raise LuminousError(f"env config: unknown option(s) {', '.join(unknown)}; expected some of "
                                f"{', '.join(sorted(known))}")
        return cls(**kwargs)

    def to_kwargs(self) -> dict[str, Any]:
        """Plain JSON data that `from_kwargs` reads back."""
        out = asdict(self)
        out["task_types"], out["room_types"], out["cdf"] = list(self.task_types), list(self.room_types), list(self.cdf)
        return out

    @property
    def visible_pixels(self) -> int:
        """Pixels an object needs to be visible: ALFRED's 10 at 300x300, scaled to this image's area."""
        if self.min_visible_pixels > 0:
            return self.min_visible_pixels
        return max(1, round(10 * self.width * self.height / (300 * 300)))


def _names(name: str, value: Any, most: int) -> tuple[str, ...]:
    """A list of names (strings; for `cdf`, paths too) as a tuple, or a LuminousError naming the field."""
    if not isinstance(value, (list, tuple)) or not all(isinstance(v, (str, os.PathLike)) for v in value) \
            or (name != "cdf" and not all(isinstance(v, str) for v in value)):
        raise LuminousError(f"env config {name}: expected a list of {'paths' if name == 'cdf' else 'names'}, "
                            f"got {short_repr(value)}")
    if len(value) > most:
        raise LuminousError(f"env config {name}: expected at most {most} entries, got {len(value)}")
    out = tuple(os.fspath(v) for v in value)
    if not all(isinstance(v, str) for v in out):
        raise LuminousError(f"env config {name}: expected text paths, got {short_repr(value)}")
    return out


def _check_reward(value: Any) -> None:
    """`reward`: a table of term name -> a finite number within +-MAX_REWARD."""
    if not isinstance(value, dict) or not all(isinstance(k, str) for k in value):
        raise LuminousError(f"env config reward: expected a table of term name -> number, got {short_repr(value)}")
    for k, v in value.items():
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or abs(v) > MAX_REWARD:
            raise LuminousError(f"env config reward.{k}: expected a finite number within +-{MAX_REWARD:g}, "
                                f"got {short_repr(v)}")


def short_repr(value: Any) -> str:
    """A value for a one-line message (long ones cut)."""
    text = repr(value).replace("\n", " ")
    return text if len(text) <= 80 else text[:77] + "..."
