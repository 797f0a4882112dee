"""An evaluation trusts nothing it has not checked (issue 27): a damaged episode file is played again, a
folder that holds no evaluation is refused, env options the evaluation sets itself are not overridden,
counts are bounded, and an agent that returns something that is not an action is recorded as its fault."""

from __future__ import annotations

import hashlib
import json
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.benchmark import benchmark_entry
from luminous_sim.errors import LuminousError
from luminous_sim.eval import EpisodeOutcome, evaluate
from luminous_sim.eval import evaluator as evaluator_module
from luminous_sim.eval.evaluator import read_outcome
from luminous_sim.eval.metrics import AGENT_FAULT
from tests.conftest import file_tree

SMALL = {"width": 64, "height": 64}
INDICES = [2, 0]


def _fake_play(env, agent, split, index, seed=0, **_where):
    """A played episode in microseconds: what the outcome files hold is what these tests are about."""
    e = benchmark_entry(split, index)
    return EpisodeOutcome(split, index, e.task_type, e.floor_plan, e.layout, end="max_failures",
                          goal_conditions=(0, 1), steps=10 + index, expert_length=40, failures=10,
                          instruction=f"do {index}")


@pytest.fixture()
def fast(monkeypatch):
    monkeypatch.setattr(evaluator_module, "play", _fake_play)


tree = file_tree


def test_a_non_empty_folder_that_holds_no_evaluation_is_refused(tmp_path, fast, capsys):
    from luminous_sim.cli.main import main

    (tmp_path / "notes.txt").write_text("mine")
    with pytest.raises(LuminousError, match=r"not empty and holds no evaluation \(run.json missing; it has notes.txt"):
        evaluate("random", "U+", [0], out_dir=tmp_path, env_kwargs=SMALL)
    assert main(["eval", "--policy", "random", "--split", "U+", "--episodes", "1", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "holds no evaluation" in err
    assert tree(tmp_path) == {"notes.txt": hashlib.sha256(b"mine").hexdigest()}


@pytest.mark.parametrize("make, match", [
    (lambda p: (p / "run.json").mkdir(), "run.json: a folder; "),
    (lambda p: (p / "run.json").write_text("[]"), "run.json: expected a JSON object"),
    (lambda p: (p / "run.json").write_text("{"), "run.json: not JSON"),
    (lambda p: (p / "episodes").write_text("x"), "episodes: not a folder"),
])
def test_a_broken_run_file_or_episodes_folder_is_named(tmp_path, fast, make, match):
    make(tmp_path)
    with pytest.raises(LuminousError, match=match):
        evaluate("random", "U+", [0], out_dir=tmp_path, env_kwargs=SMALL)


def test_an_episodes_folder_that_is_a_link_is_refused(tmp_path, fast):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    (out / "episodes").symlink_to(elsewhere)
    with pytest.raises(LuminousError, match="episodes: a symbolic link"):
        evaluate("random", "U+", [0], out_dir=out, env_kwargs=SMALL)
    assert not any(elsewhere.iterdir())


def test_env_options_the_evaluation_sets_are_not_overridden(fast, capsys):
    from luminous_sim.cli.main import main

    with pytest.raises(LuminousError, match=r"env option split='S\+': the evaluation plays split U\+"):
        evaluate("random", "U+", [0], env_kwargs={"split": "S+"})
    with pytest.raises(LuminousError, match="env option cdf="):
        evaluate("random", "U+", [0], env_kwargs={"cdf": ["a.yaml"]})
    report = evaluate("random", "U+", [0], env_kwargs={**SMALL, "split": "U+"})  # the same split: fine
    assert report.outcomes[0].split == "U+"
    assert main(["eval", "--policy", "random", "--split", "U+", "--episodes", "1", "--out", "/tmp/never-written",
                 "--env", "split=S+"]) == 2
    assert "env option split='S+'" in capsys.readouterr().err
    assert not Path("/tmp/never-written").exists()


def test_episode_counts_over_the_limit_are_refused_before_any_work(capsys):
    from luminous_sim.cli.main import main

    with pytest.raises(LuminousError, match="episodes: expected 1 to 100000"):
        evaluate("random", "U+", 2**63 - 1)
    with pytest.raises(SystemExit) as exc:
        main(["eval", "--policy", "random", "--split", "U+", "--episodes", str(2**63 - 1), "--out", "/tmp/x"])
    assert exc.value.code == 2 and "argument --episodes: expected a whole number from 1 to 100000" in \
        capsys.readouterr().err


@pytest.mark.parametrize("content, field", [
    ("", "not JSON"), ('{"split": "U+", "ind', "not JSON"), ("[]", "expected a JSON object"),
    ("{}", "field 'split' is missing"), ('{"split": "U+", "index": "0"}', "field 'index': expected a whole number"),
])
def test_a_damaged_episode_file_is_named_and_played_again(tmp_path, fast, content, field):
    reference = evaluate("random", "U+", INDICES, out_dir=tmp_path / "ref", env_kwargs=SMALL)
    out = tmp_path / "out"
    shutil.copytree(tmp_path / "ref", out)
    path = out / "episodes" / "U+-2.json"
    path.write_text(content)
    with pytest.raises(LuminousError, match=f"U\\+-2.json: {field}"):
        read_outcome(path, "U+", 2)
    again = evaluate("random", "U+", INDICES, out_dir=out, env_kwargs=SMALL)
    assert again.outcomes == reference.outcomes
    assert len(again.replayed) == 1 and "U+-2.json" in again.replayed[0] and field in again.replayed[0]
    assert tree(out) == tree(tmp_path / "ref")


@pytest.mark.parametrize("edit, field", [
    (lambda r: r | {"steps": r["steps"] + 1}, "field 'check': .* is not the digest of the file's other fields"),
    (lambda r: r | {"end": "success", "success": True, "goal_conditions": [1, 1]},
     "field 'check': .* is not the digest"),
    (lambda r: {k: v for k, v in r.items() if k != "check"}, "field 'check' is missing"),
    (lambda r: r | {"check": 7}, "field 'check': 7 is not the digest"),
])
def test_an_edited_but_well_formed_episode_file_is_detected_and_played_again(tmp_path, fast, edit, field):
    """Issue 27: an episode file carries a digest of its fields (like the build manifest's lines), so an edit
    that keeps it well-formed (steps 10 -> 11, a failure turned into a success) is not read back as is."""
    reference = evaluate("random", "U+", INDICES, out_dir=tmp_path / "ref", env_kwargs=SMALL)
    out = tmp_path / "out"
    shutil.copytree(tmp_path / "ref", out)
    path = out / "episodes" / "U+-2.json"
    path.write_text(json.dumps(edit(json.loads(path.read_text())), indent=1))
    with pytest.raises(LuminousError, match=f"U\\+-2.json: {field}"):
        read_outcome(path, "U+", 2)
    again = evaluate("random", "U+", INDICES, out_dir=out, env_kwargs=SMALL)
    assert again.outcomes == reference.outcomes and len(again.replayed) == 1
    assert tree(out) == tree(tmp_path / "ref")


def test_another_episodes_outcome_is_played_again(tmp_path, fast):
    evaluate("random", "U+", INDICES, out_dir=tmp_path, env_kwargs=SMALL)
    other = (tmp_path / "episodes" / "U+-0.json").read_text()
    (tmp_path / "episodes" / "U+-2.json").write_text(other)
    with pytest.raises(LuminousError, match=r"U\+-2.json: field 'index': 0, but the file is episode 2 of U\+"):
        read_outcome(tmp_path / "episodes" / "U+-2.json", "U+", 2)
    assert len(evaluate("random", "U+", INDICES, out_dir=tmp_path, env_kwargs=SMALL).replayed) == 1


def test_an_episode_file_that_is_a_folder_or_a_link_is_named(tmp_path, fast):
    evaluate("random", "U+", INDICES, out_dir=tmp_path, env_kwargs=SMALL)
    (tmp_path / "episodes" / "U+-2.json").unlink()
    (tmp_path / "episodes" / "U+-2.json").mkdir()
    with pytest.raises(LuminousError, match=r"U\+-2.json: a folder; expected an episode outcome file"):
        read_outcome(tmp_path / "episodes" / "U+-2.json", "U+", 2)
    victim = tmp_path / "victim.json"
    victim.write_text("precious")
    (tmp_path / "episodes" / "U+-0.json").unlink()
    (tmp_path / "episodes" / "U+-0.json").symlink_to(victim)
    report = evaluate("random", "U+", INDICES, out_dir=tmp_path, env_kwargs=SMALL)
    assert len(report.replayed) == 2 and victim.read_text() == "precious"
    assert not (tmp_path / "episodes" / "U+-0.json").is_symlink()


# ---------------------------------------------------------------- at random

JSON = st.recursive(st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=10),
                    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner, max_size=3),
                    max_leaves=5)


def _corrupt(path: Path, draw) -> None:
    data = path.read_bytes()
    kind = draw(st.sampled_from(["truncate", "splice", "whole", "field", "delete_field", "folder", "link"]))
    if kind == "truncate":
        # cut inside the JSON: dropping only the trailing newline leaves the same record, not damage
        path.write_bytes(data[: draw(st.integers(0, len(data.rstrip()) - 1))])
    elif kind == "splice":
        i = draw(st.integers(0, len(data)))
        path.write_bytes(data[:i] + draw(st.binary(min_size=1, max_size=20)) + data[i + 5:])
    elif kind == "whole":
        path.write_bytes(draw(st.sampled_from([b"[]", b"{}", b"null", b"1e999", b"[" * 5000, b"\xff\xfe"])))
    elif kind in ("field", "delete_field"):
        record = json.loads(data)
        name = draw(st.sampled_from(sorted(record)))
        if kind == "delete_field" and name in ("split", "index", "task_type", "floor_plan", "layout", "end"):
            del record[name]
        else:  # any other value: of another kind (damage) or of the same kind (an edit, caught by the digest)
            record[name] = draw(JSON.filter(lambda v, old=record[name]: v != old))
        path.write_text(json.dumps(record))
    elif kind == "folder":
        path.unlink()
        (path / "inner").mkdir(parents=True)
    else:
        path.unlink()
        path.symlink_to(path.parents[2] / "victim.json")


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_random_damage_to_episode_files_is_played_again_to_the_uninterrupted_tree(data, tmp_path_factory,
                                                                                  monkeypatch):
    monkeypatch.setattr(evaluator_module, "play", _fake_play)
    root = tmp_path_factory.mktemp("eval")
    (root / "victim.json").write_text("precious")
    reference = evaluate("random", "U+", INDICES, out_dir=root / "ref", env_kwargs=SMALL)
    out = root / "out"
    shutil.copytree(root / "ref", out)
    for name in data.draw(st.lists(st.sampled_from(["U+-2.json", "U+-0.json"]), min_size=1, max_size=2, unique=True)):
        _corrupt(out / "episodes" / name, data.draw)
    again = evaluate("random", "U+", INDICES, out_dir=out, env_kwargs=SMALL)
    assert again.outcomes == reference.outcomes and again.replayed
    assert (root / "victim.json").read_text() == "precious"
    assert tree(out) == tree(root / "ref")


# ---------------------------------------------------------------- agents' faults

class _Returns:
    def __init__(self, actions):
        self.actions = list(actions)

    def reset(self, instruction, info):
        self.left = list(self.actions)

    def act(self, observation, info):
        return self.left.pop(0) if len(self.left) > 1 else self.left[0]


def returns_none(context):
    return _Returns([None])


def returns_out_of_range(context):
    return _Returns([0, context.action_space.n + 5])


def returns_bad_mask(context):
    return _Returns([{"action": "PickupObject", "mask": [["a", "b"]]}])


def returns_empty_mask(context):
    return _Returns([{"action": "PickupObject", "mask": [[0, 1]]}, {"action": "Stop"}])


@pytest.mark.parametrize("factory, step, says", [
    ("returns_none", 1, "returned None"),
    ("returns_out_of_range", 2, "outside"),
    ("returns_bad_mask", 1, "mask runs must be pairs of integers"),
])
def test_an_agent_that_returns_no_action_ends_its_episode_with_its_fault(factory, step, says):
    report = evaluate(f"{__name__}:{factory}", "U+", [2], env_kwargs=SMALL)
    (o,) = report.outcomes
    assert (o.end, o.cause, o.success, o.steps) == ("invalid_action", AGENT_FAULT, False, step)
    assert o.detail.startswith(f"step {step}: the agent returned") and says in o.detail


def test_a_mask_that_hits_nothing_stays_an_ordinary_failed_action():
    (o,) = evaluate(f"{__name__}:returns_empty_mask", "U+", [2], env_kwargs=SMALL).outcomes
    assert o.end == "stop" and o.failures == 1 and o.cause == ""
