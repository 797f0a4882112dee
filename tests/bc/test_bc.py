"""Behaviour cloning end to end on a tiny scale: oracle demonstrations recorded (and resumed), a policy
trained whose loss falls, deterministic given the seed, and the clone acting through `luminous eval` and
`luminous bc eval`; the policy's logits follow the env's action indices and never choose an empty slot."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from luminous_sim.bc import (  # noqa: E402  (after the skip: these need torch)
    CHECKPOINT_VAR,
    PICKUP_ENV,
    BCPolicy,
    collect_demos,
    load_checkpoint,
    load_demos,
    train_bc,
)
from luminous_sim.bc.model import PolicyShape  # noqa: E402
from luminous_sim.cli.main import main  # noqa: E402
from luminous_sim.env import ActionTable  # noqa: E402
from luminous_sim.errors import LuminousError  # noqa: E402

SMALL_ENV = ["--env", "width=64", "--env", "height=64", "--env", "targets=objects", "--env", "object_slots=8"]


@pytest.fixture(scope="module")
def demos(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("demos")
    summary = collect_demos(folder, "S+", range(28, 30))
    assert summary["recorded"] + len(summary["unavailable"]) == 2 and summary["recorded"] >= 1
    return folder


@pytest.fixture(scope="module")
def checkpoint(demos, tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("ckpt") / "bc.pt"
    train_bc(demos, path, epochs=8, batch_size=8, seed=0)
    return path


def test_demos_are_oracle_successes_with_labels(demos):
    loaded = load_demos(demos)
    assert all(d.success and d.split == "S+" and d.labelled > 0 for d in loaded)
    d = loaded[0]
    assert d.rgb.shape == (len(d.actions), 64, 64, 3) and d.rgb.dtype == np.uint8
    assert d.objects.shape == (len(d.actions), PICKUP_ENV["object_slots"]) and d.tokens[0] > 0
    assert "pick up" in d.instruction and not d.failed[0]


def test_collecting_again_resumes_without_replaying(demos):
    before = {p.name: p.stat().st_mtime_ns for p in demos.glob("*.npz")}
    summary = collect_demos(demos, "S+", range(28, 30))
    assert {p.name: p.stat().st_mtime_ns for p in demos.glob("*.npz")} == before
    assert summary["recorded"] == len(before)


def test_demos_of_another_env_are_refused(demos):
    marker = demos / "collection.json"
    claim = json.loads(marker.read_text())
    other = demos.parent / "other"
    other.mkdir(exist_ok=True)
    (other / "collection.json").write_text(json.dumps({**claim, "tokens": 3}))
    with pytest.raises(LuminousError, match="another env"):
        collect_demos(other, "S+", [28])


def test_loss_falls(demos, tmp_path):
    result = train_bc(demos, tmp_path / "a.pt", epochs=8, batch_size=8, seed=0)
    assert len(result.losses) == 8 and result.losses[-1] < 0.5 * result.losses[0]
    assert result.samples == sum(d.labelled for d in load_demos(demos))


def test_training_is_deterministic_given_the_seed(demos, tmp_path):
    def weights(path: Path) -> dict:
        return load_checkpoint(path)[0].state_dict()

    train_bc(demos, tmp_path / "a.pt", epochs=2, batch_size=8, seed=3)
    train_bc(demos, tmp_path / "b.pt", epochs=2, batch_size=8, seed=3)
    train_bc(demos, tmp_path / "c.pt", epochs=2, batch_size=8, seed=4)
    a, b, c = weights(tmp_path / "a.pt"), weights(tmp_path / "b.pt"), weights(tmp_path / "c.pt")
    assert all(torch.equal(a[k], b[k]) for k in a)
    assert not all(torch.equal(a[k], c[k]) for k in a)


def test_logits_follow_the_env_indices_and_skip_empty_slots():
    slots = 4
    shape = PolicyShape(vocab=10, types=5, slots=slots, dim=8)
    torch.manual_seed(0)
    model = BCPolicy(shape).eval()
    table = ActionTable(64, 64, 3, slots)
    assert shape.actions == table.n
    objects = torch.tensor([[0, 0, 3, 0]])
    logits = model(torch.zeros(1, 64, 64, 3, dtype=torch.uint8), torch.tensor([[2, 3, 0]]), objects,
                   torch.tensor([shape.actions]), torch.tensor([False]))[0]
    live = {i for i in range(shape.actions) if logits[i] > -1e8}
    assert live == set(range(6)) | {table.index(name, 2) for name in
                                    ("PickupObject", "PutObject", "OpenObject", "CloseObject", "ToggleObjectOn",
                                     "ToggleObjectOff", "SliceObject")}


def test_the_clone_acts_through_luminous_eval(checkpoint, tmp_path, capsys, monkeypatch):
    monkeypatch.setenv(CHECKPOINT_VAR, str(checkpoint))
    code = main(["eval", "--policy", "luminous_sim.bc:bc_agent", "--split", "S+", "--episodes", "1",
                 "--out", str(tmp_path / "eval"), "--track", "privileged", *SMALL_ENV, "--env", "max_steps=30"])
    err = capsys.readouterr().err
    assert code == 0, err
    (episode,) = json.loads((tmp_path / "eval" / "report.json").read_text())["episodes"]
    assert episode["end"] != "unavailable" and episode["steps"] > 0


def test_the_clone_plays_pickup_episodes_repeatably(checkpoint, tmp_path, capsys):
    runs = []
    for name in ("a.json", "b.json"):
        code = main(["bc", "eval", "--policy", "luminous_sim.bc:bc_agent_sampling", "--checkpoint", str(checkpoint),
                     "--split", "U+", "--episodes", "1", "--out", str(tmp_path / name)])
        assert code == 0, capsys.readouterr().err
        runs.append(json.loads((tmp_path / name).read_text()))
    assert runs[0] == runs[1]
    (episode,) = runs[0]["episodes"]
    assert episode["task_type"] == "pickup_object" and episode["steps"] > 0


def test_a_clone_in_the_wrong_env_says_which_options_to_pass(checkpoint, tmp_path, capsys, monkeypatch):
    monkeypatch.setenv(CHECKPOINT_VAR, str(checkpoint))
    code = main(["eval", "--policy", "luminous_sim.bc:bc_agent", "--split", "S+", "--episodes", "1",
                 "--out", str(tmp_path / "eval")])
    err = capsys.readouterr().err
    assert code == 2 and "--env width=64" in err and "--env targets=objects" in err and "--track privileged" in err


def test_a_missing_checkpoint_is_a_clear_error(tmp_path):
    with pytest.raises(LuminousError, match="no such checkpoint"):
        load_checkpoint(tmp_path / "none.pt")
    (tmp_path / "junk.pt").write_bytes(b"not a checkpoint")
    with pytest.raises(LuminousError, match="not a behaviour-cloning checkpoint"):
        load_checkpoint(tmp_path / "junk.pt")
