"""`EnvConfig`: everything that defines one environment id, as plain JSON-serialisable values, made of one
pydantic model per concern (`config_parts`: observations, actions, rewards, source, limits; each task kind's
options in `kinds.options`).

The keyword arguments of `LuminousEnv` (and so of a spec in `envs/*.toml`, and of `--env KEY=VALUE`) are the
fields of those concerns, flat; a wrong name or type is a `LuminousError` that names the field and what was
expected. A config reads flat (`config.width`) or by concern (`config.observations.width`).
"""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from luminous_sim.env.config_parts import (
    FIELD_PART,
    IMAGE_SIZE,
    MAX_CDF_FILES,
    MAX_GRID,
    MAX_NAMES,
    MAX_OBJECT_SLOTS,
    MAX_REWARD,
    MAX_SCENE_ATTEMPTS,
    MAX_STEPS,
    PARTS,
    RASTERISERS,
    REWARD_MODES,
    TARGET_KINDS,
    ActionSettings,
    LimitSettings,
    ObservationSettings,
    RewardSettings,
    Settings,
    SourceSettings,
    settings_error,
    short_repr,
)
from luminous_sim.env.kinds.options import MAX_TASK_DISTANCE
from luminous_sim.errors import LuminousError

__all__ = ["IMAGE_SIZE", "MAX_CDF_FILES", "MAX_GRID", "MAX_NAMES", "MAX_OBJECT_SLOTS", "MAX_REWARD",
           "MAX_SCENE_ATTEMPTS", "MAX_STEPS", "MAX_TASK_DISTANCE", "RASTERISERS", "REWARD_MODES", "TARGET_KINDS",
           "EnvConfig", "short_repr"]


class EnvConfig:
    """One environment's definition (ALFRED's camera, limits and reward configuration by default).

    Every field is checked when the config is made (so when the env is made); a value of the wrong type or
    out of its range is a one-line `LuminousError` naming the field and what was expected. Limits
    (`config_parts`' constants): `width`, `height` 16..1024 (`IMAGE_SIZE`); `grid` 1..32 and at most the
    image's shorter side (`MAX_GRID`); `object_slots` 1..256 (`MAX_OBJECT_SLOTS`); `max_steps`, `max_failures`
    1..1,000,000 (`MAX_STEPS`); `scene_attempts` 1..100 (`MAX_SCENE_ATTEMPTS`); `min_visible_pixels`
    0..width x height; `reward` values finite, within +-1e6 (`MAX_REWARD`); `task_types`, `room_types` at
    most 64 entries (`MAX_NAMES`); `cdf` at most 10,000 files (`MAX_CDF_FILES`); each kind's options within
    their ranges (`kinds.options`). Room types that cannot go with the task types (ALFRED's table) are
    refused when the env is made (`env.episodes.check_rooms`).

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
            reset; see `luminous_sim.episodes.cdf`): a CDF's own task is the goal, else a task of
            `task_types` is drawn. `reset(options={"cdf": path, "scene_seed": s})` does the same for one
            episode of any env; () (the default) generates scenes on the fly.
        task_options: options of the task kinds, by name (`luminous_sim.env.kinds.KIND_OPTIONS`: `objectnav`'s
            `success_distance` and `min_start_distance` in metres, `objectnav_pickup`'s `min_start_distance`);
            each kind takes its own, the rest keep their defaults.
    """

    observations: ObservationSettings
    actions: ActionSettings
    rewards: RewardSettings
    source: SourceSettings
    limits: LimitSettings

    def __init__(self, **kwargs: Any):
        unknown = sorted(set(kwargs) - set(FIELD_PART))
        if unknown:
            raise LuminousError(f"env config: unknown option(s) {', '.join(unknown)}; expected some of "
                                f"{', '.join(sorted(FIELD_PART))}")
        for part, model in PARTS.items():
            given = {k: v for k, v in kwargs.items() if FIELD_PART[k] == part}
            try:
                object.__setattr__(self, part, model(**given))
            except ValidationError as exc:
                raise settings_error(exc, given) from None
        self.source.check()
        self.rewards.config()  # unknown terms
        if self.grid > min(self.width, self.height):
            raise LuminousError(f"env config grid: {self.grid} points a side do not fit a {self.width}x{self.height}"
                                " image")
        for name in ("step_instructions", "high_descs"):
            if getattr(self.observations, name) and not self.verify_expert:
                raise LuminousError(f"env config {name}: needs verify_expert (they describe the expert's plan)")

    @classmethod
    def from_kwargs(cls, kwargs: dict[str, Any]) -> EnvConfig:
        """The config of `LuminousEnv(**kwargs)`; an unknown name is a LuminousError listing the known ones."""
        return cls(**kwargs)

    def to_kwargs(self) -> dict[str, Any]:
        """Plain JSON data that `from_kwargs` reads back (every field, lists for the tuples)."""
        out: dict[str, Any] = {}
        for part in PARTS:
            for name, value in getattr(self, part).model_dump().items():
                out[name] = list(value) if isinstance(value, tuple) else value
        return out

    def parts(self) -> dict[str, Settings]:
        """The concerns, by name."""
        return {part: getattr(self, part) for part in PARTS}

    def __getattr__(self, name: str) -> Any:
        part = FIELD_PART.get(name)
        if part is None or part not in self.__dict__:
            raise AttributeError(f"EnvConfig has no field {name!r}")
        return getattr(self.__dict__[part], name)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"EnvConfig is frozen ({name}): make another, EnvConfig(**{{**config.to_kwargs(), ...}})")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, EnvConfig) and self.parts() == other.parts()

    def __hash__(self) -> int:
        return hash(tuple(sorted((k, repr(v)) for k, v in self.to_kwargs().items())))

    def __repr__(self) -> str:
        return f"EnvConfig({', '.join(f'{k}={v!r}' for k, v in self.to_kwargs().items())})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (EnvConfig.from_kwargs, (self.to_kwargs(),))

    @property
    def visible_pixels(self) -> int:
        """Pixels an object needs to be visible: ALFRED's 10 at 300x300, scaled to this image's area."""
        return self.observations.visible_pixels

