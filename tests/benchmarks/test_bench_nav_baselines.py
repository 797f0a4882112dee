"""benchmarks/bench_nav_baselines.py: a trained policy (`--ppo NAME=DIR`) plays the same held-out episodes as the
baselines, in the observation options and wrappers it was trained with."""

from __future__ import annotations

import importlib.util
import json

import pytest

from tests.conftest import load_script

ID = "Luminous-ObjectNav-64-v2"


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_nav_baselines.py")


@pytest.mark.skipif(importlib.util.find_spec("stable_baselines3") is None, reason="stable-baselines3 not installed")
def test_a_trained_policy_plays_the_baselines_episodes_with_its_own_observations(bench, tmp_path):
    import sys

    from stable_baselines3 import PPO

    from luminous_sim.env.actions import NAVIGATION, STOP

    sys.path.insert(0, str(bench.ROOT / "examples"))
    import train_ppo

    kwargs = {"goal_mask": True, "depth": True, "reward": {"failed_stop": -1.0}}
    actions = [*NAVIGATION, STOP]
    env = train_ppo.make_env(ID, train_ppo.observation_kwargs(kwargs), feedback=True, actions=actions)
    assert "goal_mask" in env.observation_space.spaces
    PPO("MultiInputPolicy", env, n_steps=16, batch_size=16, seed=0, device="cpu").save(tmp_path / "model.zip")
    env.close()
    (tmp_path / "config.json").write_text(json.dumps({"env_id": ID, "env_kwargs": kwargs, "feedback": True,
                                                      "actions": actions}))
    out = tmp_path / "nav.json"
    assert bench.main(["--env", ID, "--episodes", "1", "--policies", "oracle", "--ppo", f"p={tmp_path}",
                       "--json", str(out)]) == 0
    result = json.loads(out.read_text())["ids"][ID]
    oracle, trained = result["episodes"]["oracle"][0], result["episodes"]["ppo:p"][0]
    assert oracle["success"] and trained["seed"] == oracle["seed"]
    for key in ("shortest_path_length", "start_distance", "target", "room"):  # the same episode
        assert trained[key] == oracle[key]
    assert result["policies"]["ppo:p"]["episodes"] == 1


def test_a_policy_trained_on_another_id_is_refused(bench, tmp_path):
    (tmp_path / "config.json").write_text(json.dumps({"env_id": "Luminous-PickUp-64-v2", "env_kwargs": {}}))
    (tmp_path / "model.zip").write_bytes(b"")
    with pytest.raises(SystemExit, match="trained on Luminous-PickUp-64-v2, not Luminous-ObjectNav-64-v2"):
        bench.trained_player(ID, tmp_path, 0)
    with pytest.raises(SystemExit, match="trained on Luminous-PickUp-64-v2"):  # a run's other model, its config
        bench.trained_player(ID, tmp_path / "model_warm.zip", 0)
