"""examples/train_ppo.py end to end on a tiny budget: a few hundred PPO steps, the files it promises, a saved
model that loads and acts, and a resumed run that goes on from the save."""

from __future__ import annotations

import csv
import json
import sys

import pytest

from tests.conftest import load_script

pytest.importorskip("stable_baselines3")

ENV = "Luminous-NavToObject-64-v1"
TINY = ["--env", ENV, "--ppo", "n_steps=64", "--ppo", "batch_size=32", "--ppo", "n_epochs=1",
        "--env-kwarg", "max_steps=40"]


@pytest.fixture(scope="module")
def train_ppo():
    yield from load_script("examples/train_ppo.py")


def _curve(path):
    with path.open() as fh:
        return list(csv.DictReader(fh))


def test_train_save_evaluate_and_resume(tmp_path, train_ppo, capsys):
    from stable_baselines3 import PPO

    out = tmp_path / "ppo"
    assert train_ppo.main([*TINY, "--steps", "128", "--eval-episodes", "2", "--out", str(out)]) == 0
    for name in ("model.zip", "curve.csv", "curve.png", "config.json", "eval.json", "progress.json",
                 "vecnormalize.pkl"):
        assert (out / name).is_file() and (out / name).stat().st_size > 0, name
    assert (out / "curve.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    rows = _curve(out / "curve.csv")
    assert rows and list(rows[0]) == list(train_ppo.CURVE_FIELDS)
    assert all(0 < int(r["timesteps"]) <= 128 and int(r["success"]) in (0, 1) for r in rows)
    cpu = [float(r["cpu_seconds"]) for r in rows]
    assert cpu == sorted(cpu) and cpu[0] > 0
    report = json.loads((out / "eval.json").read_text())
    assert report["timesteps"] == 128 and set(report) >= {"random", "random-nav", "ppo", "seeds"}
    assert report["random"]["episodes"] == report["ppo"]["episodes"] == report["random-nav"]["episodes"] == 2
    assert sum(report["ppo"]["ends"].values()) == 2 and set(report["ppo"]["ends"]) <= {"success", "stop", "failures",
                                                                                     "steps"}
    lo, hi = report["ppo"]["ci95"]
    assert 0 <= lo <= report["ppo"]["success_rate"] <= hi <= 1
    config = json.loads((out / "config.json").read_text())
    assert config["env_kwargs"] == {**train_ppo.TRAIN_KWARGS, "max_steps": 40} and config["ppo"]["n_steps"] == 64
    assert config["feedback"] and config["scene_repeats"] == 4 and config["failure_limit_ends"]
    progress = json.loads((out / "progress.json").read_text())
    assert progress["timesteps"] == 128 and progress["cpu_seconds"] >= cpu[-1]

    env = train_ppo.make_env(ENV, train_ppo.observation_kwargs(config["env_kwargs"]), feedback=True)
    model = PPO.load(out / "model.zip", device="cpu")
    assert model.action_space == env.action_space  # (SB3 keeps the image channels first in its own space)
    obs, _ = env.reset(seed=7)
    action, _ = model.predict(obs)
    assert env.action_space.contains(int(action))
    env.step(int(action))
    env.close()

    assert train_ppo.main([*TINY, "--steps", "192", "--eval-episodes", "0", "--out", str(out), "--resume"]) == 0
    resumed = _curve(out / "curve.csv")
    assert resumed[: len(rows)] == rows and len(resumed) > len(rows)
    assert PPO.load(out / "model.zip", device="cpu").num_timesteps == 192
    assert json.loads((out / "eval.json").read_text())["timesteps"] == 192
    assert json.loads((out / "progress.json").read_text())["cpu_seconds"] > progress["cpu_seconds"]


def test_a_cpu_budget_stops_training(tmp_path, train_ppo):
    """The budget counts the trainer and its env workers; training stops at the first check past it."""
    out = tmp_path / "cpu"
    from luminous_sim.env.actions import NAVIGATION

    model = train_ppo.train(ENV, out, 100_000, env_kwargs={"max_steps": 40}, n_envs=2, cpu_budget_s=3.0,
                            ppo_kwargs={"n_steps": 32, "batch_size": 32, "n_epochs": 1}, actions=NAVIGATION)
    progress = json.loads((out / "progress.json").read_text())
    assert 3.0 <= progress["cpu_seconds"] and model.num_timesteps < 100_000
    config = json.loads((out / "config.json").read_text())
    assert config["processes"] and config["actions"] == list(NAVIGATION) and model.action_space.n == len(NAVIGATION)
    outcomes = train_ppo.run_episodes(train_ppo.model_policy(model), ENV, [5], {"max_steps": 20}, feedback=True,
                                      actions=NAVIGATION)
    assert outcomes[0].length <= 20 and outcomes[0].end in ("success", "failures", "steps")
    # resuming with the budget spent trains no further
    again = train_ppo.train(ENV, out, 100_000, env_kwargs={"max_steps": 40}, n_envs=2, cpu_budget_s=3.0,
                            ppo_kwargs={"n_steps": 32, "batch_size": 32, "n_epochs": 1}, actions=NAVIGATION,
                            resume=True)
    assert again.num_timesteps == model.num_timesteps


def test_cpu_seconds_counts_live_worker_processes(train_ppo):
    import subprocess

    child = subprocess.Popen([sys.executable, "-c", "import time\nt = time.process_time()\n"
                              "while time.process_time() - t < 0.5: pass\ntime.sleep(30)"])
    try:
        import time

        deadline = time.monotonic() + 20
        while train_ppo.cpu_seconds([child.pid]) - train_ppo.cpu_seconds() < 0.4 and time.monotonic() < deadline:
            time.sleep(0.1)
        assert train_ppo.cpu_seconds([child.pid]) - train_ppo.cpu_seconds() >= 0.4
        assert train_ppo.cpu_seconds([2**22 + 12345]) < train_ppo.cpu_seconds() + 0.1  # no such process: skipped
    finally:
        child.kill()
        child.wait()


def test_bad_env_options_are_refused(train_ppo):
    with pytest.raises(SystemExit, match="name=value"):
        train_ppo.main(["--out", "x", "--env-kwarg", "max_steps"])


def test_a_policy_is_evaluated_with_the_observation_options_it_was_trained_with(train_ppo):
    kwargs = {"depth": True, "reward": {"failure": -0.2}, "max_steps": 40, "verify_expert": False, "pose": True}
    assert train_ppo.observation_kwargs(kwargs) == {"depth": True, "pose": True}
    assert train_ppo.observation_kwargs(train_ppo.TRAIN_KWARGS) == {"depth": True}
