"""Proof of no change (issue 41): every registered id's scripted episode, and the reset sources beside
generation, digest as committed in `episode_digests.json` (made by `scripts/episode_digests.py` at the commit
before the episodes package, c475006; a difference names the part that changed: observations, rewards, infos or the
expert's plan). A sample runs in the fast suite, every id in the slow one."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.conftest import load_script

COMMITTED = json.loads((Path(__file__).parent / "episode_digests.json").read_text())
SAMPLE = ("Luminous-PickUp-64-v2", "Luminous-ObjectNav-64-v2", "Luminous-Text-v0")
SOURCES = ("split", "scene", "cdf", "trial")


@pytest.fixture(scope="module")
def digests():
    yield from load_script("scripts/episode_digests.py")


def test_every_registered_id_has_a_committed_digest(digests):
    assert set(digests.registered_ids()) <= set(COMMITTED)


@pytest.mark.parametrize("env_id", SAMPLE)
def test_a_sample_of_ids_plays_as_committed(digests, env_id):
    assert digests.id_digests(env_id) == COMMITTED[env_id]


def test_every_sensor_and_measure_plays_as_committed(digests):
    """Depth, segmentation, the goal mask, the pose, the inventory and the expert's suggestion, which no id has."""
    env_id, kwargs = digests.CONFIGURED["every sensor"]
    assert digests.id_digests(env_id, **kwargs) == COMMITTED[f"{env_id}:every sensor"]


@pytest.mark.slow
@pytest.mark.parametrize("name", ["object slots"])
def test_the_other_settings_play_as_committed(digests, name):
    env_id, kwargs = digests.CONFIGURED[name]
    assert digests.id_digests(env_id, **kwargs) == COMMITTED[f"{env_id}:{name}"]


def test_the_digest_sees_a_changed_observation(digests, monkeypatch):
    """Negative control: an env whose rgb is off by one pixel value digests differently."""
    import luminous_sim.env.alfred_env as alfred_env

    original = alfred_env.LuminousEnv._observation

    def brighter(self):
        obs = original(self)
        obs["rgb"][0, 0, 0] ^= 1
        return obs

    monkeypatch.setattr(alfred_env.LuminousEnv, "_observation", brighter)
    got = digests.id_digests(SAMPLE[0])
    assert got["observations"] != COMMITTED[SAMPLE[0]]["observations"]
    assert got["rewards"] == COMMITTED[SAMPLE[0]]["rewards"]


@pytest.mark.slow
@pytest.mark.parametrize("env_id", sorted(k for k in COMMITTED if ":" not in k and " " not in k))
def test_every_id_plays_as_committed(digests, env_id):
    assert digests.id_digests(env_id) == COMMITTED[env_id]


@pytest.mark.slow
@pytest.mark.parametrize("source", SOURCES)
def test_every_reset_source_plays_as_committed(digests, source, tmp_path):
    assert digests.source_digests(source, tmp_path) == COMMITTED[f"{digests.SOURCES_ID}:{source}"]


@pytest.mark.slow
def test_a_split_entry_builds_as_committed(digests, tmp_path):
    assert digests.build_digest(tmp_path) == COMMITTED["dataset build U+ 0"]
