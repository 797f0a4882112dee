"""Issue 27, the env contract: `step` after the episode ended raises `ResetNeeded` (naming `reset`) and touches
nothing, while gymnasium's and stable-baselines3's vector envs still run over episode ends (they reset an
ended env, never step it); room types that cannot go with the task types are refused when the env is made;
`reset(options=...)` refuses unknown keys, exclusive combinations and wrong types with a `LuminousError`
naming the option; every size and count of `EnvConfig` has a stated limit. A property throws random reset
options and random actions (after the end too) and sees no exception but the documented ones."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import gymnasium
import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import LuminousEnv, ResetNeeded, load_entries
from luminous_sim.env.config import (
    IMAGE_SIZE,
    MAX_CDF_FILES,
    MAX_GRID,
    MAX_NAMES,
    MAX_OBJECT_SLOTS,
    MAX_SCENE_ATTEMPTS,
    MAX_STEPS,
    EnvConfig,
)
from luminous_sim.env.episodes import cdf_paths, check_rooms, requested_entry, room_types
from luminous_sim.env.reset_options import RESET_OPTIONS, ResetOptions, reset_options
from luminous_sim.errors import LuminousError

SMALL = "Luminous-PickUp-64-v1"
APPLE = str(Path(__file__).resolve().parents[2] / "cdf" / "examples" / "kitchen_apple_fridge.yaml")
HEAT = "pick_heat_then_place_in_recep"


def one_line(exc: pytest.ExceptionInfo[BaseException]) -> str:
    text = str(exc.value)
    assert "\n" not in text
    return text


@pytest.fixture(scope="module")
def env():
    """A small env whose episodes are cheap: no expert proof, short limits."""
    e = gymnasium.make(SMALL, verify_expert=False, max_steps=6, max_failures=3).unwrapped
    e.reset(seed=0)
    yield e
    e.close()


@pytest.fixture(scope="module")
def scene(env):
    """The scene of the env's first episode (`options={"scene": scene}` replays it, reusing its world)."""
    return env.episode.scene


# ------------------------------------------------------------------ step after the end


def test_step_after_stop_raises_reset_needed_and_leaves_the_world_alone(env, scene):
    env.reset(seed=1, options={"scene": scene})
    _, _, terminated, truncated, _ = env.step(env.actions.index("Stop"))
    assert terminated and not truncated
    pose, steps = env.world.agent, env._steps
    with pytest.raises(ResetNeeded, match=r"call reset\(\)") as exc:
        env.step(env.actions.index("MoveAhead"))
    assert isinstance(exc.value, LuminousError) and isinstance(exc.value, gymnasium.error.ResetNeeded)
    one_line(exc)
    assert env.world.agent == pose and env._steps == steps
    env.reset(seed=1, options={"scene": scene})
    assert env.step(env.actions.index("RotateLeft"))[2:4] == (False, False)  # a reset starts it again


def test_through_gymnasiums_wrappers_too(env, scene):
    from gymnasium.wrappers import OrderEnforcing, PassiveEnvChecker

    wrapped = OrderEnforcing(PassiveEnvChecker(env))
    wrapped.reset(seed=1, options={"scene": scene})
    assert wrapped.step(env.actions.index("Stop"))[2]
    with pytest.raises(ResetNeeded, match=r"reset\(\)"):
        wrapped.step(0)


def test_step_after_truncation_raises_reset_needed(env, scene):
    env.reset(seed=2, options={"scene": scene})
    ended = False
    for _ in range(env.config.max_steps):
        _, _, terminated, truncated, _ = env.step(env.actions.index("RotateLeft"))
        ended = terminated or truncated
        if ended:
            break
    assert ended and truncated
    with pytest.raises(ResetNeeded, match="ended"):
        env.step(env.actions.index("RotateLeft"))


def test_step_before_the_first_reset_is_reset_needed_too():
    with pytest.raises(ResetNeeded, match=r"reset\(\)"):
        LuminousEnv(task_types=["pickup_object"], width=64, height=64).step(0)


def test_the_ended_state_survives_pickling(env, scene):
    import pickle

    env.reset(seed=3, options={"scene": scene})
    env.step(env.actions.index("Stop"))
    copy = pickle.loads(pickle.dumps(env))
    try:
        with pytest.raises(ResetNeeded):
            copy.step(0)
    finally:
        copy.close()


def test_vector_envs_run_over_episode_ends():
    """Gymnasium's vector envs (next-step autoreset) and SB3's DummyVecEnv reset an ended env, never step it."""
    make = [lambda: gymnasium.make(SMALL, verify_expert=False, max_steps=2)]
    envs = gymnasium.vector.SyncVectorEnv(make)
    try:
        envs.reset(seed=0)
        ends = []
        for _ in range(4):  # the episode ends at step 2; step 3 resets it (next-step autoreset); step 4 steps
            _, _, terminated, truncated, _ = envs.step(np.array([envs.single_action_space.n - 1]))
            ends.append(bool(terminated[0] or truncated[0]))
        assert ends == [False, True, False, False]
    finally:
        envs.close()
    envs = gymnasium.vector.AsyncVectorEnv(make * 2)
    try:
        envs.reset(seed=0)
        for _ in range(4):  # ends at steps 2 and 4, resets at step 3
            envs.step(np.array([1, 2]))
    finally:
        envs.close()

    from stable_baselines3.common.vec_env import DummyVecEnv

    from luminous_sim.env import InstructionTokens

    vec = DummyVecEnv([lambda: InstructionTokens(gymnasium.make(SMALL, verify_expert=False, max_steps=2))])
    try:
        vec.seed(0)
        vec.reset()
        dones = [bool(vec.step(np.array([1]))[2][0]) for _ in range(3)]
        assert dones == [False, True, False]  # reset at once on the end
    finally:
        vec.close()


# ------------------------------------------------------------------ room types and task types


def test_a_task_type_no_room_type_allows_is_refused_naming_both_and_its_rooms():
    with pytest.raises(LuminousError, match="room_types") as exc:
        gymnasium.make("Luminous-ALFRED-v1", room_types=["Bathroom"], task_types=[HEAT])
    text = one_line(exc)
    assert "Bathroom" in text and HEAT in text and "only in Kitchen" in text


def test_only_the_task_types_that_do_not_fit_are_named():
    with pytest.raises(LuminousError) as exc:
        LuminousEnv(room_types=["Bathroom"], task_types=["pick_and_place_simple", HEAT, "goto_object"])
    text = one_line(exc)
    assert HEAT in text and "pick_and_place_simple" not in text and "goto_object" not in text


def test_a_room_type_no_task_type_is_played_in_is_refused():
    with pytest.raises(LuminousError, match="room_types: no task of pick_heat_then_place_in_recep is played in "
                                            "Bedroom"):
        check_rooms(EnvConfig(room_types=("Kitchen", "Bedroom"), task_types=(HEAT,)))


def test_there_is_no_fallback_to_other_rooms_and_fitting_configs_pass():
    with pytest.raises(LuminousError, match="only in Kitchen"):
        room_types(EnvConfig(room_types=("Bathroom",), task_types=(HEAT,)), HEAT)
    config = EnvConfig(room_types=("Kitchen", "Bathroom"), task_types=(HEAT, "pick_clean_then_place_in_recep"))
    check_rooms(config)
    assert room_types(config, HEAT) == ["Kitchen"]
    for entry in load_entries():  # every shipped id
        check_rooms(EnvConfig.from_kwargs(entry.kwargs))


# ------------------------------------------------------------------ reset options

BAD_OPTIONS: list[tuple[dict[str, Any], Any, str]] = [
    # (config kwargs, options, what the message says)
    ({}, {"colour": "red"}, "unknown key.*'colour'; expected some of scene, split, index, trial, cdf, scene_seed"),
    ({}, [("scene", None)], "reset options: expected a dict"),
    ({}, {"scene": "kitchen"}, "scene: expected a luminous_sim.scene.Scene, got str"),
    ({}, {"split": 3}, r"split: expected one of S\+, U\+, U\+test, got 3"),
    ({}, {"split": "V+"}, r"split: expected one of .*got 'V\+'"),
    ({"split": "U+"}, {"index": 1.5}, "index: expected a whole number"),
    ({"split": "U+"}, {"index": "3"}, "index: expected a whole number"),
    ({"split": "U+"}, {"index": True}, "index: expected a whole number"),
    ({"split": "U+"}, {"index": 2**63}, "index: expected a whole number in 0"),
    ({}, {"index": 3}, "index: names an episode of a split; give 'split' too"),
    ({}, {"cdf": 3}, "cdf: expected a CDF file path"),
    ({}, {"cdf": []}, "cdf: expected a CDF file path or a non-empty list"),
    ({}, {"cdf": "nope.yaml"}, "cdf: 'nope.yaml': no such CDF file"),
    ({}, {"cdf": ["x"] * (MAX_CDF_FILES + 1)}, f"cdf: expected at most {MAX_CDF_FILES} files"),
    ({}, {"scene_seed": 3}, "scene_seed: seeds the scene of a CDF; give 'cdf' too"),
    ({}, {"cdf": APPLE, "scene_seed": -1}, "scene_seed: expected a whole number"),
    ({}, {"scene": object(), "split": "U+"}, "'scene' and 'split' exclude each other"),
    ({}, {"split": "U+", "index": 0, "cdf": APPLE}, "'split' and 'cdf' exclude each other"),
    ({"split": "U+"}, {"index": 0, "scene_seed": 1}, "'index' and 'scene_seed' exclude each other"),
    ({}, {"scene": object(), "cdf": APPLE}, "'scene' and 'cdf' exclude each other"),
]


@pytest.mark.parametrize("kwargs, options, message", BAD_OPTIONS)
def test_bad_reset_options_are_named(kwargs, options, message):
    with pytest.raises(LuminousError, match=message) as exc:
        reset_options(options, EnvConfig(**kwargs))
    assert type(exc.value) is LuminousError
    one_line(exc)


def test_a_refused_reset_changes_nothing(env, scene):
    env.reset(seed=4, options={"scene": scene})
    episode, world = env.episode, env.world
    with pytest.raises(LuminousError, match="unknown key"):
        env.reset(seed=5, options={"scen": scene})
    assert env.episode is episode and env.world is world
    env.step(env.actions.index("RotateLeft"))


def test_good_reset_options_read_into_a_typed_object():
    config = EnvConfig()
    assert reset_options(None, config) == reset_options({}, config) == ResetOptions()
    assert reset_options({"scene": None, "split": None}, config) == ResetOptions()  # None is not given
    got = reset_options({"split": "U+", "index": np.int64(3)}, config)
    assert got == ResetOptions(split="U+", index=3) and type(got.index) is int and got.source == "split"
    got = reset_options({"cdf": Path(APPLE), "scene_seed": np.array(7)}, config)
    assert got == ResetOptions(cdf=(APPLE,), scene_seed=7) and got.source == "cdf"
    assert reset_options({"scene_seed": 2}, EnvConfig(cdf=APPLE)).scene_seed == 2   # the env's CDFs
    assert reset_options({"index": 2}, EnvConfig(split="S+")).index == 2           # the env's split
    assert set(RESET_OPTIONS) == {"scene", "split", "index", "trial", "cdf", "scene_seed"}


def test_a_source_in_the_options_replaces_the_envs_own():
    split_env, cdf_env = EnvConfig(split="U+"), EnvConfig(cdf=APPLE)
    rng = np.random.default_rng(0)
    asked = reset_options({"cdf": APPLE}, split_env)
    assert requested_entry(split_env, asked, rng) is None and cdf_paths(split_env, asked) == (APPLE,)
    asked = reset_options({"split": "U+", "index": 2}, cdf_env)
    assert cdf_paths(cdf_env, asked) == () and requested_entry(cdf_env, asked, rng) is not None
    assert requested_entry(split_env, ResetOptions(), rng) is not None and cdf_paths(cdf_env, ResetOptions())


# ------------------------------------------------------------------ EnvConfig limits

LOW, HIGH = IMAGE_SIZE


@pytest.mark.parametrize("field, value, message", [
    ("width", 100_000, f"width: expected an integer in {LOW}..{HIGH}, got 100000"),
    ("width", LOW - 1, f"width: expected an integer in {LOW}..{HIGH}"),
    ("height", 0, "height: expected an integer in"),
    ("height", HIGH + 1, "height: expected an integer in"),
    ("grid", 0, f"grid: expected an integer in 1..{MAX_GRID}"),
    ("grid", MAX_GRID + 1, f"grid: expected an integer in 1..{MAX_GRID}"),
    ("object_slots", MAX_OBJECT_SLOTS + 1, f"object_slots: expected an integer in 1..{MAX_OBJECT_SLOTS}"),
    ("max_steps", 0, f"max_steps: expected an integer in 1..{MAX_STEPS}"),
    ("max_steps", MAX_STEPS + 1, "max_steps: expected an integer in"),
    ("max_failures", MAX_STEPS + 1, "max_failures: expected an integer in"),
    ("scene_attempts", MAX_SCENE_ATTEMPTS + 1, f"scene_attempts: expected an integer in 1..{MAX_SCENE_ATTEMPTS}"),
    ("min_visible_pixels", -1, "min_visible_pixels: expected an integer in 0..90000"),
    ("min_visible_pixels", 90_001, "min_visible_pixels: expected an integer in 0..90000"),
    ("width", 64.0, "width: expected an integer, got 64.0"),
    ("reward", {"goal_reward": float("nan")}, r"reward.goal_reward: expected a finite number within \+-1e\+06"),
    ("reward", {"goal_reward": float("inf")}, "reward.goal_reward: expected a finite number"),
    ("reward", {"goal_reward": 1e7}, "reward.goal_reward: expected a finite number"),
    ("reward", {"goal_reward": True}, "reward.goal_reward: expected a finite number"),
    ("reward", {1: 1.0}, "reward: expected a table"),
    ("reward", [1.0], "reward: expected a table"),
    ("task_types", 5, "task_types: expected a list of names, got 5"),
    ("task_types", ["goto_object"] * (MAX_NAMES + 1), f"task_types: expected at most {MAX_NAMES} entries"),
    ("room_types", "Kitchen", "room_types: expected a list of names"),
    ("cdf", 3, "cdf: expected a list of paths, got 3"),
    ("cdf", [APPLE] * (MAX_CDF_FILES + 1), f"cdf: expected at most {MAX_CDF_FILES} entries"),
    ("cdf", "nope.yaml", "cdf: nope.yaml: no such CDF file"),
])
def test_every_size_and_count_has_a_stated_limit(field, value, message):
    with pytest.raises(LuminousError, match=message) as exc:
        EnvConfig(**{field: value})
    one_line(exc)


def test_the_env_refuses_a_huge_image_before_any_work():
    with pytest.raises(LuminousError, match="width: expected an integer in 16..1024, got 100000"):
        gymnasium.make("Luminous-ALFRED-v1", width=100_000)


def test_the_limits_themselves_are_accepted():
    assert EnvConfig(width=LOW, height=LOW, grid=LOW).grid == LOW
    assert EnvConfig(width=HIGH, height=HIGH, grid=MAX_GRID, object_slots=MAX_OBJECT_SLOTS, max_steps=MAX_STEPS,
                     max_failures=MAX_STEPS, scene_attempts=MAX_SCENE_ATTEMPTS, min_visible_pixels=HIGH * HIGH,
                     reward={"goal_reward": -1e6}).width == HIGH
    assert EnvConfig(cdf=Path(APPLE)).cdf == (APPLE,)


# ------------------------------------------------------------------ a property over the whole surface

VALUES = st.one_of(
    st.none(), st.booleans(), st.integers(-(2**70), 2**70), st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=4), st.sampled_from(["U+", "S+", "V+", "", "nope.yaml", APPLE]),
    st.lists(st.one_of(st.integers(), st.text(max_size=3)), max_size=2), st.just(object()),
)
OPTIONS = st.dictionaries(st.one_of(st.sampled_from([*RESET_OPTIONS, "seed", "Scene"]), st.integers()), VALUES,
                          max_size=3)
ACTIONS = st.one_of(
    st.integers(-3, 80), st.sampled_from([5, 10**30, -(10**30), np.int64(2), np.array(0), np.array([1, 2])]),
    st.floats(allow_nan=True), st.none(), st.text(max_size=4), st.booleans(),
    st.fixed_dictionaries({"action": st.sampled_from(["MoveAhead", "Stop", "<<stop>>", "PickupObject",
                                                      "PutObject", "OpenObject", "Fly", 3])},
                          optional={"point": VALUES, "mask": VALUES, "objectId": VALUES}),
)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(junk=OPTIONS, actions=st.lists(ACTIONS, max_size=9))
def test_random_options_and_actions_raise_only_the_documented_errors(env, scene, junk, actions):
    options = {"scene": scene, **junk}
    try:
        checked = reset_options(options, env.config)
    except LuminousError:
        with pytest.raises(LuminousError):
            env.reset(seed=0, options=options)
        checked = None
        event("options refused")
    if checked is None or checked.source != "scene":  # another source costs a scene generation: not here
        options = {"scene": scene}
    env.reset(seed=0, options=options)
    ended = False
    for action in actions:
        if ended:
            with pytest.raises(ResetNeeded):
                env.step(action)
            event("a step after the end")
            continue
        obs, reward, terminated, truncated, _ = env.step(action)
        assert env.observation_space.contains(obs) and np.isfinite(reward)
        ended = terminated or truncated


# ------------------------------------------------------------------ reset's seed and the wrappers' arguments


@pytest.mark.parametrize("seed", ["3", -1, 1.5, True, [1], 2.0])
def test_a_bad_seed_is_a_luminous_error_naming_seed(env, seed):
    """Issue 27: checked before gymnasium's own `gymnasium.error.Error`, and before anything changes."""
    episode, world = env.episode, env.world
    with pytest.raises(LuminousError, match=r"reset seed: expected a whole number >= 0 or None, got ") as exc:
        env.reset(seed=seed)
    one_line(exc)
    assert not isinstance(exc.value, gymnasium.error.Error)
    assert env.episode is episode and env.world is world


def test_a_numpy_seed_is_taken_as_its_value(env, scene):
    env.reset(seed=np.int64(4), options={"scene": scene})
    a = env.np_random.integers(1000)
    env.reset(seed=4, options={"scene": scene})
    assert env.np_random.integers(1000) == a


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"space": "boxes"}, "InstructionTokens space: expected 'multidiscrete' or 'box', got 'boxes'"),
    ({"length": 0}, "InstructionTokens length: expected a whole number from 1 to 1000 "
                    "(luminous_sim.limits.MAX_INSTRUCTION_TOKENS), got 0"),
    ({"length": 10**12}, "InstructionTokens length: expected a whole number from 1"),
    ({"length": "32"}, "InstructionTokens length: expected a whole number from 1"),
])
def test_bad_wrapper_arguments_are_luminous_errors_naming_them(kwargs, message):
    from luminous_sim.env import InstructionTokens

    inner = gymnasium.make(SMALL, verify_expert=False)
    try:
        with pytest.raises(LuminousError) as exc:
            InstructionTokens(inner, **kwargs)
        assert one_line(exc).startswith(message), exc.value
        assert isinstance(exc.value, ValueError)  # as before, for code that caught ValueError
    finally:
        inner.close()
