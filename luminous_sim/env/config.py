"""`EnvConfig`: everything that defines one environment id, as plain JSON-serialisable values.

The keyword arguments of `LuminousEnv` (and so of a spec in `envs/*.toml`) are exactly this dataclass's
fields; a wrong name or type is a `LuminousError` that names the field and what was expected.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field, fields
from pathlib import Path
from typing import Any

from luminous_sim.env.kinds import KIND_OPTIONS, TASK_KINDS
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES, ROOM_TYPES

REWARD_MODES: tuple[str, ...] = ("dense", "sparse")
TARGET_KINDS: tuple[str, ...] = ("points", "objects")


@dataclass(frozen=True)
class EnvConfig:
    """One environment's definition (ALFRED's camera, limits and reward configuration by default).

    Attributes:
        task_types: the task kinds an episode draws from (uniformly): ALFRED's types, `goto_object`,
            `pickup_object` (`luminous_sim.env.kinds.TASK_KINDS`).
        room_types: the room types scenes are generated in; empty means every room type the drawn task
            type allows (ALFRED's table).
        width: image width in pixels.
        height: image height in pixels.
        targets: what an interaction action targets: `points` (a k x k grid of image points) or `objects`
            (visible-object slots, listed in an `objects` observation).
        grid: k, the side of the k x k grid of image points (`points` targets).
        object_slots: the number of visible-object slots (`objects` targets).
        depth: add a `depth` observation (float32 metres).
        segmentation: add a `segmentation` observation (int32 instance index, -1 for background).
        pose: add a `pose` observation (x, y metres, yaw and horizon degrees).
        inventory: add an `inventory` observation (index of the held object's type, 0 for none).
        step_instructions: follow the goal directive in `instruction` with step-by-step instructions (the
            language layer's templates over the expert's plan; needs `verify_expert`).
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
    pose: bool = False
    inventory: bool = False
    step_instructions: bool = False
    max_steps: int = 1000
    max_failures: int = 10
    reward_mode: str = "dense"
    reward: dict[str, float] = field(default_factory=dict)
    navigation_reward: bool = True
    expert_in_info: bool = False
    verify_expert: bool = True
    scene_attempts: int = 8
    min_visible_pixels: int = 0
    split: str = ""
    cdf: tuple[str, ...] = ()
    task_options: dict[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "cdf" and isinstance(value, str):
                object.__setattr__(self, "cdf", (value,))
            elif f.name in ("task_types", "room_types", "cdf"):
                if isinstance(value, str) or not all(isinstance(v, str) for v in value):
                    raise LuminousError(f"env config {f.name}: expected a list of names, got {value!r}")
                object.__setattr__(self, f.name, tuple(value))
            elif f.name in ("reward", "task_options"):
                if not isinstance(value, dict) or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                                          for v in value.values()):
                    raise LuminousError(f"env config {f.name}: expected a table of numbers, got {value!r}")
            elif f.type == "bool" and not isinstance(value, bool):
                raise LuminousError(f"env config {f.name}: expected true or false, got {value!r}")
            elif f.type == "int" and (isinstance(value, bool) or not isinstance(value, int)):
                raise LuminousError(f"env config {f.name}: expected an integer, got {value!r}")
            elif f.type == "str" and not isinstance(value, str):
                raise LuminousError(f"env config {f.name}: expected a string, got {value!r}")
        self._check_values()

    def _check_values(self) -> None:
        bad = [t for t in self.task_types if t not in TASK_KINDS]
        if not self.task_types or bad:
            raise LuminousError(f"env config task_types: {bad or 'empty'}; expected some of {', '.join(TASK_KINDS)}")
        known = {o for t in self.task_types for o in KIND_OPTIONS.get(t, ())}
        bad = sorted(set(self.task_options) - known)
        if bad:
            raise LuminousError(f"env config task_options: {bad}; the task types {', '.join(self.task_types)} take "
                                f"{', '.join(sorted(known)) or 'none'}")
        if any(v < 0 for v in self.task_options.values()):
            raise LuminousError(f"env config task_options: expected distances >= 0, got {self.task_options}")
        bad = [r for r in self.room_types if r not in ROOM_TYPES]
        if bad:
            raise LuminousError(f"env config room_types: {bad}; expected some of {', '.join(ROOM_TYPES)}")
        if self.targets not in TARGET_KINDS:
            raise LuminousError(f"env config targets: {self.targets!r}; expected one of {TARGET_KINDS}")
        if self.reward_mode not in REWARD_MODES:
            raise LuminousError(f"env config reward_mode: {self.reward_mode!r}; expected one of {REWARD_MODES}")
        for name in ("width", "height", "grid", "object_slots", "max_steps", "max_failures", "scene_attempts"):
            if getattr(self, name) < 1:
                raise LuminousError(f"env config {name}: expected a positive integer, got {getattr(self, name)}")
        if self.step_instructions and not self.verify_expert:
            raise LuminousError("env config step_instructions: needs verify_expert (they describe the expert's plan)")
        if self.split:
            from luminous_sim.splits import PLUS_SPLITS  # only when asked: `import luminous_sim` stays cheap

            if self.split not in PLUS_SPLITS:
                raise LuminousError(f"env config split: {self.split!r}; expected one of {', '.join(PLUS_SPLITS)}")
        if self.cdf and self.split:
            raise LuminousError("env config: give split or cdf, not both (where would the scenes come from?)")
        missing = [p for p in self.cdf if not Path(p).is_file()]
        if missing:
            raise LuminousError(f"env config cdf: {', '.join(missing)}: no such CDF file")
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
