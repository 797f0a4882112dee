"""The env is wiring of typed parts: its config is one pydantic model per concern (with each task kind's options
declared once), its observations are sensors, its `info` is measures, its episodes come from sources; the
flat surface (`gym.make(id, **kwargs)`, `to_kwargs()`) stays as it was."""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np
import pytest
from gymnasium import spaces

import luminous_sim.env.measures as measures_module
import luminous_sim.env.sensors as sensors_module
from luminous_sim.env import LuminousEnv, load_entries
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.config_parts import FIELD_PART, PARTS
from luminous_sim.env.kinds import KIND_OPTIONS, task_kind
from luminous_sim.env.kinds.options import KIND_OPTION_MODELS
from luminous_sim.env.measures import Measure, Step
from luminous_sim.env.sensors import Reading, Sensor
from luminous_sim.env.sources import SOURCES, GeneratedSource
from luminous_sim.errors import LuminousError

FLAT_FIELDS = {
    "task_types", "room_types", "width", "height", "targets", "grid", "object_slots", "depth", "segmentation",
    "instance_types", "goal_mask", "pose", "inventory", "step_instructions", "high_descs", "max_steps", "max_failures",
    "reward_mode", "reward", "navigation_reward", "expert_in_info", "verify_expert", "scene_attempts",
    "min_visible_pixels", "rasteriser", "split", "cdf", "task_options"}
"""The keyword arguments an env took before its config was split by concern (evaluations resume from them)."""
SMALL = {"task_types": ["pickup_object"], "width": 32, "height": 32, "room_types": ["Bathroom"], "grid": 3,
         "max_steps": 20, "rasteriser": "compiled"}


def test_the_flat_keywords_are_the_concerns_fields_each_in_one():
    assert set(FIELD_PART) == FLAT_FIELDS
    assert sum(len(m.model_fields) for m in PARTS.values()) == len(FLAT_FIELDS)
    config = EnvConfig(width=64, height=48, max_steps=7, reward_mode="sparse")
    assert (config.observations.width, config.observations.height, config.limits.max_steps) == (64, 48, 7)
    assert config.rewards.reward_mode == config.reward_mode == "sparse" and config.width == 64


@pytest.mark.parametrize("entry", load_entries(), ids=lambda e: e.id)
def test_every_registered_config_reads_back_from_its_kwargs(entry):
    config = EnvConfig.from_kwargs(entry.kwargs)
    again = EnvConfig.from_kwargs(config.to_kwargs())
    assert again == config and set(config.to_kwargs()) == FLAT_FIELDS
    assert {k: config.to_kwargs()[k] for k in entry.kwargs} == {
        k: list(v) if isinstance(v, tuple) else v for k, v in entry.kwargs.items()}


def test_a_config_is_frozen_and_names_a_field_it_lacks():
    config = EnvConfig()
    with pytest.raises(AttributeError, match="frozen"):
        config.width = 3  # type: ignore[misc]
    with pytest.raises(AttributeError, match="no field 'colour'"):
        _ = config.colour


def test_each_kinds_options_are_declared_once_and_checked():
    assert KIND_OPTIONS == {k: tuple(m.model_fields) for k, m in KIND_OPTION_MODELS.items()}
    for name, model in KIND_OPTION_MODELS.items():
        assert dict(task_kind(name).defaults) == model().model_dump()
    assert task_kind("objectnav").configured({"success_distance": 1.5}).options["success_distance"] == 1.5
    with pytest.raises(LuminousError, match=r"task_options.cross_room_share: expected a number in 0..1"):
        EnvConfig(task_types=["pick_and_place_simple"], task_options={"cross_room_share": 2.0})
    with pytest.raises(LuminousError, match=r"task_options: \['house'\]; the task types objectnav take"):
        EnvConfig(task_types=["objectnav"], task_options={"house": 1.0})


class Brightness(Sensor):
    """A sensor a user adds: the frame's mean brightness."""

    key: ClassVar[str] = "brightness"

    @classmethod
    def wanted(cls, config: EnvConfig, actions: Any) -> bool:
        return True

    def space(self) -> spaces.Space:
        return spaces.Box(0.0, 255.0, (1,), np.float32)

    def read(self, reading: Reading) -> np.ndarray:
        return np.array([reading.frame.rgb[..., :3].mean()], np.float32)


class StepsTaken(Measure):
    """A measure a user adds: steps taken so far."""

    def reset(self, env: LuminousEnv) -> None:
        self.steps = 0

    def update(self, env: LuminousEnv, step: Step) -> None:
        self.steps += 1

    def info(self, env: LuminousEnv, step: Step | None) -> dict[str, Any]:
        return {"steps_taken": self.steps}


def test_a_new_observation_is_one_sensor_and_a_new_info_key_one_measure(monkeypatch):
    monkeypatch.setattr(sensors_module, "SENSORS", (*sensors_module.SENSORS, Brightness))
    monkeypatch.setattr(measures_module, "MEASURES", (*measures_module.MEASURES, StepsTaken))
    env = LuminousEnv(**SMALL)
    try:
        assert "brightness" in env.observation_space.spaces
        obs, info = env.reset(seed=0)
        assert env.observation_space.contains(obs)
        assert obs["brightness"][0] == pytest.approx(obs["rgb"].mean())
        assert info["steps_taken"] == 0
        _, _, _, _, info = env.step(env.actions.index("RotateLeft"))
        assert info["steps_taken"] == 1 and info["failures"] == 0
    finally:
        env.close()


def test_the_observation_space_is_the_wanted_sensors():
    env = LuminousEnv(**SMALL, depth=True, pose=True)
    try:
        assert list(env.observation_space.spaces) == sorted(["rgb", "instruction", "depth", "pose"])
        assert [s.key for s in env.sensors] == ["rgb", "instruction", "depth", "pose"]
    finally:
        env.close()


def test_generation_is_the_last_source_and_always_applies():
    assert isinstance(SOURCES[-1], GeneratedSource)
    assert [type(s).__name__ for s in SOURCES] == ["SplitSource", "TrialSource", "CdfSource", "GeneratedSource"]
