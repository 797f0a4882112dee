"""Oracle demonstrations as a Minari dataset: written by `luminous dataset minari`, read back with minari's own
loaders, the same actions as the oracle's own episodes, resumable, and refusing what it cannot write."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.data.minari_export import MinariExportError, default_minari_id, export_minari, minari_dataset_path
from luminous_sim.env import InstructionTokens, OraclePolicy
from tests.cli.test_errors import one_line_error, run

minari = pytest.importorskip("minari")

NAV = "Luminous-NavToObject-64-v1"
KWARGS = {"max_steps": 60}


def oracle_episode(env_id: str, seed: int, **kwargs) -> tuple[list[int], list[float], str]:
    """(actions, rewards, instruction) of the oracle's episode in a fresh env."""
    env = InstructionTokens(gymnasium.make(env_id, **kwargs))
    policy = OraclePolicy(env)
    obs, _ = env.reset(seed=seed)
    instruction = env.unwrapped.episode.goal.instruction
    actions, rewards, done = [], [], False
    while not done:
        action = policy(obs)
        obs, reward, terminated, truncated, _ = env.step(action)
        actions.append(action)
        rewards.append(reward)
        done = terminated or truncated
    env.close()
    return actions, rewards, instruction


def test_the_cli_writes_a_dataset_minari_loads(tmp_path, capsys, monkeypatch):
    out = tmp_path / "minari"
    code, stdout, err = run(["dataset", "minari", "--env", NAV, "--episodes", "2", "--seed", "3", "--out", str(out),
                             "--env-kwarg", "max_steps=60"], capsys)
    assert code == 0, err
    dataset_id = default_minari_id(NAV)
    assert dataset_id == "luminous/NavToObject-64-v1/oracle-v0" and "wrote 2 oracle episodes" in stdout
    assert not out.with_name("minari.partial").exists()

    monkeypatch.setenv("MINARI_DATASETS_PATH", str(out))
    dataset = minari.load_dataset(dataset_id)
    assert dataset.total_episodes == 2 and dataset.storage.metadata["algorithm_name"] == "luminous_sim.env.OraclePolicy"
    meta = list(dataset.storage.get_episode_metadata([0, 1]))
    assert [int(m["seed"]) for m in meta] == [3, 4] and dataset.storage.metadata["luminous_skipped_seeds"] == []

    env = dataset.recover_environment()  # the wrapped env, rebuilt from the recorded spec
    assert env.observation_space == dataset.observation_space and env.action_space == dataset.action_space
    env.close()
    for episode, m in zip(dataset.iterate_episodes(), meta):
        actions, rewards, instruction = oracle_episode(NAV, int(m["seed"]), **KWARGS)
        assert episode.actions.tolist() == actions and np.allclose(episode.rewards, rewards)
        assert m["instruction"] == instruction and m["task_type"] == "goto_object"
        assert episode.terminations[-1] and not episode.truncations.any() and episode.infos["success"][-1]
        assert episode.observations["rgb"].shape == (len(actions) + 1, 64, 64, 3)
        first = {k: v[0] for k, v in episode.observations.items()}
        assert dataset.observation_space.contains(first) and (first["instruction"] > 1).sum() == len(
            instruction.split())
        assert episode.infos["goal_conditions_total"].tolist() == [1] * (len(actions) + 1)
    assert sum(len(e) for e in dataset.iterate_episodes()) == dataset.total_steps


def test_an_interrupted_export_resumes_to_the_same_dataset(tmp_path, monkeypatch):
    import luminous_sim.data.minari_export as mx

    real, calls = mx._rollout, []

    def dies_on_the_second(env, seed, episode_id):
        calls.append(seed)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(env, seed, episode_id)

    out = tmp_path / "ds"
    monkeypatch.setattr(mx, "_rollout", dies_on_the_second)
    with pytest.raises(KeyboardInterrupt):
        export_minari(NAV, 2, out, env_kwargs=KWARGS)
    assert not out.exists() and (tmp_path / "ds.partial").is_dir()
    with pytest.raises(MinariExportError, match="resume"):
        export_minari(NAV, 2, out, env_kwargs=KWARGS)
    with pytest.raises(MinariExportError, match="same arguments"):
        export_minari(NAV, 2, out, seed=5, env_kwargs=KWARGS, resume=True)
    monkeypatch.setattr(mx, "_rollout", real)
    done = export_minari(NAV, 2, out, env_kwargs=KWARGS, resume=True)
    assert (done.episodes, done.seeds_tried, done.skipped_seeds) == (2, 2, ())
    dataset = minari.MinariDataset(minari_dataset_path(out, done.dataset_id))
    assert [e.actions.tolist() for e in dataset.iterate_episodes()] == [oracle_episode(NAV, s, **KWARGS)[0]
                                                                       for s in (0, 1)]
    with pytest.raises(MinariExportError, match="already exists"):
        export_minari(NAV, 1, out)


def test_episodes_outside_the_discrete_space_are_left_out_and_counted(tmp_path):
    # PickUp-64, seed 0: the target of the oracle's PickupObject covers none of the 3 x 3 grid points
    actions, _, _ = oracle_episode("Luminous-PickUp-64-v1", 0)
    assert any(isinstance(a, dict) for a in actions)  # ... so the oracle acts in ALFRED's dict form
    with pytest.raises(MinariExportError, match="targets=objects"):
        export_minari("Luminous-PickUp-64-v1", 1, tmp_path / "ds", max_seeds=1)


def test_bad_arguments_are_one_line_errors(tmp_path, capsys):
    for argv in (["--env", "Luminous-Nope-v0", "--episodes", "1"], ["--env", NAV, "--episodes", "0"],
                 ["--env", NAV, "--episodes", "1", "--env-kwarg", "max_steps"],
                 ["--env", NAV, "--episodes", "1", "--env-kwarg", "colour=3"]):
        code, _, err = run(["dataset", "minari", *argv, "--out", str(tmp_path / "x")], capsys)
        assert code == 2 and one_line_error(err), (argv, err)


def test_a_relative_out_writes_where_an_absolute_one_would(tmp_path, capsys, monkeypatch):
    # the documented `--out out/minari`: Minari joined a relative datasets root onto itself (main_data.hdf5 not found)
    monkeypatch.chdir(tmp_path)
    code, stdout, err = run(["dataset", "minari", "--env", NAV, "--episodes", "1", "--out", "out/minari",
                             "--env-kwarg", "max_steps=60"], capsys)
    assert code == 0, err
    out = tmp_path / "out" / "minari"
    assert "wrote 1 oracle episodes" in stdout and str(out) in stdout
    assert not (tmp_path / "out" / "minari.partial").exists()
    dataset = minari.MinariDataset(minari_dataset_path(out, default_minari_id(NAV)))
    assert dataset.total_episodes == 1 and [int(m["seed"]) for m in dataset.storage.get_episode_metadata([0])] == [0]
    (episode,) = dataset.iterate_episodes()
    assert episode.actions.tolist() == oracle_episode(NAV, 0, **KWARGS)[0]


def test_a_partial_torn_while_the_dataset_was_created_starts_afresh_on_resume(tmp_path, monkeypatch):
    # what the relative --out bug left behind: Minari's metadata and an empty main_data.hdf5, no run recorded
    from minari.dataset.minari_storage import MinariStorage

    def torn(self):
        raise FileNotFoundError("main_data.hdf5")

    out, dataset_id = tmp_path / "ds", default_minari_id(NAV)
    store = minari_dataset_path(tmp_path / "ds.partial", dataset_id)
    with monkeypatch.context() as m:
        m.setattr(MinariStorage, "get_size", torn)
        with pytest.raises(FileNotFoundError):
            export_minari(NAV, 1, out, env_kwargs=KWARGS)
    assert (store / "metadata.json").is_file() and not out.exists()
    with pytest.raises(MinariExportError, match="before its first episode.*--resume"):
        export_minari(NAV, 1, out, env_kwargs=KWARGS)
    done = export_minari(NAV, 1, out, seed=2, env_kwargs=KWARGS, resume=True)
    assert (done.episodes, done.seeds_tried) == (1, 1) and not (tmp_path / "ds.partial").exists()
    dataset = minari.MinariDataset(minari_dataset_path(out, dataset_id))
    assert dataset.storage.metadata["luminous_first_seed"] == 2 and dataset.total_episodes == 1


def test_a_partial_that_is_not_our_own_is_never_removed(tmp_path):
    store = minari_dataset_path(tmp_path / "ds.partial", default_minari_id(NAV))
    store.mkdir(parents=True)
    (store / "metadata.json").write_text('{"total_episodes": 0, "algorithm_name": "someone else"}')
    with pytest.raises(MinariExportError, match="cannot resume"):
        export_minari(NAV, 1, tmp_path / "ds", env_kwargs=KWARGS, resume=True)
    assert (store / "metadata.json").read_text() == '{"total_episodes": 0, "algorithm_name": "someone else"}'
