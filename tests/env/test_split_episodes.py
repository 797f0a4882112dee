"""Episodes of a frozen split in the env: `episodes.entry_spec` of the entry (its layout, task, start and
initial state), the same every time; a split named at construction or at reset; clear errors; an entry the
expert cannot solve in this env raises `EpisodeUnavailable` (cause `expert`)."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
import luminous_sim.episodes.split as split_module
from luminous_sim.benchmark import benchmark_entry, benchmark_size
from luminous_sim.env import UNAVAILABLE_CAUSES, EnvConfig, EpisodeUnavailable
from luminous_sim.env.episodes import requested_entry
from luminous_sim.env.reset_options import ResetOptions, reset_options
from luminous_sim.episodes import Solution
from luminous_sim.errors import LuminousError

ENTRY = benchmark_entry("U+", 2)   # examine


def alfred(**kwargs):
    return gymnasium.make("Luminous-ALFRED-v1", **kwargs).unwrapped


def test_a_split_entry_gives_its_layout_task_and_start_the_same_every_time():
    a, b = alfred(), alfred(split="U+")
    obs_a, info_a = a.reset(seed=1, options={"split": "U+", "index": 2})
    obs_b, info_b = b.reset(seed=9, options={"index": 2})   # the env's seed does not enter a split episode
    scene = a.episode.scene
    assert scene.room.name == ENTRY.floor_plan and scene.seed == ENTRY.layout_seed
    assert info_a["task_type"] == ENTRY.task_type and a.episode.expert is not None
    assert a.world.agent == ENTRY.start and info_a["episode_key"] == ENTRY.episode_key
    assert b.episode.scene == scene and b.episode.goal.to_dict() == a.episode.goal.to_dict()
    assert obs_a["instruction"] == obs_b["instruction"] and np.array_equal(obs_a["rgb"], obs_b["rgb"])
    assert info_a == info_b
    a.close(), b.close()


def test_a_plain_reset_of_a_split_env_draws_an_entry_of_its_types():
    config = EnvConfig(split="S+")
    drawn = [requested_entry(config, ResetOptions(), np.random.default_rng(s)) for s in range(20)]
    assert drawn == [requested_entry(config, ResetOptions(), np.random.default_rng(s)) for s in range(20)]
    assert all(e is not None and e.split == "S+" and 0 <= e.index < benchmark_size("S+") for e in drawn)
    assert len({e.index for e in drawn if e is not None}) > 10
    heat = EnvConfig(split="U+", task_types=("pick_heat_then_place_in_recep",))
    picked = [requested_entry(heat, ResetOptions(), np.random.default_rng(s)) for s in range(10)]
    assert {e.task_type for e in picked if e is not None} == {"pick_heat_then_place_in_recep"}
    assert requested_entry(EnvConfig(), ResetOptions(), np.random.default_rng(0)) is None   # generated on the fly
    options = reset_options({"split": "U+", "index": np.int64(3)}, EnvConfig())
    assert requested_entry(EnvConfig(), options, np.random.default_rng(0)) == benchmark_entry("U+", 3)


@pytest.mark.parametrize("kwargs, options, message", [
    ({}, {"index": 3}, "give 'split' too"),
    ({"split": "U+"}, {"index": True}, "index: expected a whole number"),
    ({"split": "U+"}, {"index": -1}, "index: expected a whole number in 0.*got -1"),
    ({"split": "U+"}, {"index": 10**6}, "index: 1000000; split U+ holds episodes 0..434"),
    ({}, {"split": "V+", "index": 0}, "split: expected one of S+, U+, U+test, got 'V+'"),
    ({"task_types": ["pick_and_place_simple"]}, {"split": "U+", "index": 2},
     "U+ episode 2 is a look_at_obj_in_light task; this env plays only pick_and_place_simple"),
])
def test_bad_split_requests_are_clear_errors(kwargs, options, message):
    config = EnvConfig(**kwargs)
    with pytest.raises(LuminousError, match=message.replace("+", r"\+").replace("..", r"\.\.")):
        requested_entry(config, reset_options(options, config), np.random.default_rng(0))


def test_the_config_refuses_an_unknown_split():
    with pytest.raises(LuminousError, match="env config split: 'S'; expected one of S\\+, U\\+, U\\+test"):
        EnvConfig(split="S")
    with pytest.raises(LuminousError, match="expected a string"):
        EnvConfig(split=1)  # type: ignore[arg-type]
    assert EnvConfig.from_kwargs(EnvConfig(split="U+").to_kwargs()).split == "U+"


def test_an_entry_the_expert_cannot_solve_in_this_env_is_reported(monkeypatch):
    monkeypatch.setattr(split_module, "solve", lambda spec, worlds: Solution(None, "expert"))
    env = alfred()
    with pytest.raises(EpisodeUnavailable, match="the expert does not solve") as caught:
        env.reset(options={"split": "U+", "index": 2})
    assert caught.value.cause == "expert" and UNAVAILABLE_CAUSES == ("expert",)
    assert caught.value.entry == ENTRY and "U+ episode 2 (look_at_obj_in_light in" in str(caught.value)
    with pytest.raises(gymnasium.error.ResetNeeded):
        env.step(0)
    env.close()
