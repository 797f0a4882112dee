"""LuminousEnv: the Gymnasium contract (check_env, no warnings), seeded determinism, invalid actions,
termination and truncation, the ALFRED dict form, rendering, pickling and vector envs."""

from __future__ import annotations

import pickle
import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import LuminousEnv
from luminous_sim.env.actions import INTERACTIONS, NAVIGATION, ActionTable
from luminous_sim.errors import LuminousError

SMALL = "Luminous-PickUp-64-v1"
ALL_OBS = {"depth": True, "segmentation": True, "goal_mask": True, "pose": True, "inventory": True}


def small(**kwargs) -> LuminousEnv:
    return gymnasium.make(SMALL, **kwargs).unwrapped


def test_check_env_passes_without_warnings():
    env = small(**ALL_OBS)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env, skip_render_check=True)
    env.close()


def test_check_env_passes_at_alfred_size():
    env = gymnasium.make("Luminous-ALFRED-PickPlace-v1", room_types=["Bathroom"]).unwrapped
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env, skip_render_check=True)
    obs, _ = env.reset(seed=1)
    assert obs["rgb"].shape == (300, 300, 3) and env.action_space.n == 6 + 7 * 25
    env.close()


def test_same_seed_same_scene_task_and_first_observation():
    a, b = small(), small()
    obs_a, info_a = a.reset(seed=7)
    obs_b, info_b = b.reset(seed=7)
    assert a.episode.scene == b.episode.scene and obs_a["instruction"] == obs_b["instruction"]
    assert np.array_equal(obs_a["rgb"], obs_b["rgb"]) and info_a == info_b
    for action in (0, 1, 2, 0, 3):
        sa, sb = a.step(action), b.step(action)
        assert np.array_equal(sa[0]["rgb"], sb[0]["rgb"]) and sa[1:] == sb[1:]
    other, _ = b.reset(seed=8)
    assert b.episode.scene != a.episode.scene or other["instruction"] != obs_a["instruction"]
    a.close(), b.close()


def test_observations_lie_in_the_space_and_match_the_world():
    env = small(**ALL_OBS)
    obs, _ = env.reset(seed=3)
    assert env.observation_space.contains(obs)
    assert obs["depth"].dtype == np.float32 and obs["depth"].shape == (64, 64, 1)
    p = env.world.agent
    assert obs["pose"].tolist() == pytest.approx([p.x, p.y, p.rotation, p.horizon])
    assert obs["inventory"] == 0
    assert env.render_mode is None and env.render() is None
    env.close()


def test_invalid_actions_cost_a_step_and_a_failure_never_an_exception():
    env = small(max_failures=4)
    env.reset(seed=2)
    cases = [(10_000, "invalid_argument"), ("MoveAhead", "invalid_argument"),
             ({"action": "TeleportFull", "x": 0}, "unknown_action"), ({"action": "HeatObject"}, "unknown_action")]
    for k, (action, code) in enumerate(cases, 1):
        _obs, reward, terminated, truncated, info = env.step(action)
        assert info["failure_code"] == code and info["failures"] == k and info["error"]
        assert reward == pytest.approx(-0.05 - 0.01 * (k > len(env.episode.expert.actions)))
        assert truncated == (k == 4) and not terminated
    env.close()


def test_a_failed_world_action_reports_the_world_code():
    env = small()
    env.reset(seed=2)
    table = env.actions
    _, _, _, _, info = env.step(table.index("PutObject", 0))  # nothing is held
    assert info["failure_code"] in ("not_holding", "no_target")
    env.close()


def test_stop_terminates_without_success_and_max_steps_truncates():
    env = small(max_steps=3)
    env.reset(seed=4)
    _, _, terminated, truncated, info = env.step(env.actions.index("Stop"))
    assert terminated and not truncated and not info["success"]
    env.reset(seed=4)
    results = [env.step(env.actions.index("RotateLeft")) for _ in range(3)]
    assert [r[3] for r in results] == [False, False, True] and not any(r[2] for r in results)
    env.close()


def test_the_alfred_dict_form_with_a_mask_reaches_the_goal_as_the_expert_does():
    from luminous_sim.world import interaction_args

    env = small()
    env.reset(seed=0)
    while True:
        api = env.expert.next_api(env.history)
        if api is None:
            break
        name = api["action"]
        if name in INTERACTIONS:  # what an ALFRED model sends: the name and a predicted RLE mask
            mask = env.world.instance_masks()[api["objectId"]]
            action = {"action": name, "mask": interaction_args(mask)["mask"]}
        else:
            action = {"action": name}
        env.expert.suggested(len(env.history), action)
        _, _, terminated, truncated, info = env.step(action)
        assert info["failure_code"] is None, info
        if terminated or truncated:
            break
    assert info["success"] and info["goal_conditions"][0] == info["goal_conditions"][1]
    env.close()


def test_sparse_reward_pays_only_the_goal():
    env = small(reward_mode="sparse", max_failures=2)
    env.reset(seed=0)
    assert env.step(10_000)[1] == 0.0
    env.close()


def test_a_given_scene_is_played_and_top_down_renders():
    env = small()
    env.reset(seed=5)
    scene = env.episode.scene
    env.reset(seed=6, options={"scene": scene})
    assert env.episode.scene == scene
    image = env.top_down()
    assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    env.close()


def test_render_mode_rgb_array_returns_the_agents_view():
    env = gymnasium.make(SMALL, render_mode="rgb_array")
    assert env.unwrapped.render() is None  # no world before the first reset
    obs, _ = env.reset(seed=1)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.shape == (64, 64, 3) and np.array_equal(frame, obs["rgb"])
    obs, *_ = env.step(env.unwrapped.actions.index("RotateLeft"))
    assert np.array_equal(env.render(), obs["rgb"])
    env.close()


def test_without_a_render_mode_render_returns_none():
    env = small()
    env.reset(seed=1)
    assert env.render_mode is None and env.render() is None
    env.close()


def test_the_env_pickles_mid_episode():
    env = small(pose=True)
    env.reset(seed=9)
    for action in (1, 0, 0, 2):
        env.step(action)
    copy = pickle.loads(pickle.dumps(env))
    assert copy.history == env.history and copy.episode.scene == env.episode.scene
    for action in (0, 1, 3):
        a, b = env.step(action), copy.step(action)
        assert np.array_equal(a[0]["rgb"], b[0]["rgb"]) and np.array_equal(a[0]["pose"], b[0]["pose"])
        assert a[1:] == b[1:]
    assert env.reset()[0]["instruction"] == copy.reset()[0]["instruction"]  # the random stream came along
    env.close(), copy.close()


def test_async_vector_env_with_two_workers():
    envs = gymnasium.vector.AsyncVectorEnv([lambda: gymnasium.make(SMALL)] * 2)
    try:
        obs, _ = envs.reset(seed=[0, 1])
        assert obs["rgb"].shape == (2, 64, 64, 3) and len(obs["instruction"]) == 2
        for _ in range(3):
            obs, reward, _terminated, _truncated, _info = envs.step(envs.action_space.sample())
            assert reward.shape == (2,)
    finally:
        envs.close()


def test_action_table_round_trips_and_points_lie_in_the_image():
    table = ActionTable(64, 48, 3)
    assert table.n == 6 + 7 * 9 == len(table.labels())
    for i in range(table.n):
        api = table.decode(i)
        cell = None
        if "point" in api:
            x, y = api["point"]
            assert 0 <= x < 64 and 0 <= y < 48
            cell = table.points().index((x, y))
        assert table.index(api["action"], cell) == i
    assert [table.decode(i)["action"] for i in range(5)] == list(NAVIGATION)


def test_bad_options_are_named():
    with pytest.raises(LuminousError, match="reward_mode"):
        LuminousEnv(reward_mode="shaped")
    with pytest.raises(LuminousError, match="unknown option"):
        LuminousEnv(colour="red")
    with pytest.raises(LuminousError, match="unknown term"):
        LuminousEnv(reward={"bonus": 1.0})


def test_step_instructions_follow_the_directive():
    env = gymnasium.make("Luminous-ALFRED-PickPlace-v1", step_instructions=True, room_types=["Bathroom"]).unwrapped
    obs, _ = env.reset(seed=0)
    directive = env.episode.goal.instruction
    assert obs["instruction"].startswith(directive + ". ") and len(obs["instruction"]) > len(directive) + 20
    assert env.observation_space.contains(obs)
    with pytest.raises(LuminousError, match="step_instructions"):
        LuminousEnv(step_instructions=True, verify_expert=False)
    env.close()


def test_object_slot_targets_pass_check_env_and_name_visible_objects():
    from luminous_sim.vocab import ALL_TYPES

    env = small(targets="objects", object_slots=8, max_failures=50)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env, skip_render_check=True)
    obs, _ = env.reset(seed=0)
    assert env.action_space.n == 6 + 7 * 8 and env.observation_space.contains(obs)
    slots = env.slots
    visible = env.world.visible_objects()
    assert all(o in visible for o in slots) and [visible[o] for o in slots] == sorted(visible[o] for o in slots)[::-1]
    assert [ALL_TYPES[k - 1] for k in obs["objects"][: len(slots)]] == [env.world.view().state[o].object_type
                                                                        for o in slots]
    assert not obs["objects"][len(slots):].any()
    empty = env.actions.index("PickupObject", len(slots)) if len(slots) < 8 else None
    if empty is not None:
        assert env.step(empty)[4]["failure_code"] == "no_target"
    env.close()


def test_the_oracle_acts_through_object_slots():
    from luminous_sim.env import OraclePolicy

    env = small(targets="objects")
    policy = OraclePolicy(env)
    env.reset(seed=1)
    kinds = []
    terminated = truncated = False
    while not (terminated or truncated):
        action = policy()
        kinds.append(isinstance(action, (int, np.integer)))
        _, _, terminated, truncated, info = env.step(action)
    assert info["success"] and all(kinds)  # the target is in view, so it has a slot
    env.close()


def test_action_table_with_object_slots():
    table = ActionTable(64, 64, 3, slots=4)
    assert table.n == 6 + 7 * 4 == len(table.labels())
    assert table.decode(table.index("OpenObject", 1), ["A|1", "B|2"]) == {"action": "OpenObject", "objectId": "B|2"}
    put = table.decode(table.index("PutObject", 0), ["A|1"])
    assert put["receptacleObjectId"] == "A|1" and "objectId" not in put
    from luminous_sim.env.actions import EmptySlot

    with pytest.raises(EmptySlot):
        table.decode(table.index("OpenObject", 3), ["A|1"])
