"""The evaluator on a few U+ episodes: the oracle succeeds with full path weight, random fails, the same
split/index/seed gives the same outcome, an entry with no episode is reported with its cause, outputs
resume, and a user's agent runs through MODULE:CALLABLE."""

from __future__ import annotations

import json
import re

import pytest

from luminous_sim.benchmark import benchmark_entry
from luminous_sim.env import EpisodeUnavailable
from luminous_sim.errors import LuminousError
from luminous_sim.eval import (
    EpisodeJob,
    EpisodeOutcome,
    PolicyError,
    check_policy,
    evaluate,
    map_ordered,
    run_job,
    write_reports,
)
from luminous_sim.eval.evaluator import outcome_record

INDICES = [2, 0]
"""U+ 2 (examine) and U+ 0 (pick and place)."""


@pytest.fixture(scope="module")
def oracle_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("oracle")


@pytest.fixture(scope="module")
def oracle(oracle_dir):
    return evaluate("oracle", "U+", INDICES, out_dir=oracle_dir)


@pytest.fixture(scope="module")
def random_run():
    return evaluate("random", "U+", INDICES, seed=3)


def test_the_oracle_succeeds_in_expert_length(oracle):
    assert [o.index for o in oracle.outcomes] == INDICES
    for o in oracle.outcomes:
        entry = benchmark_entry("U+", o.index)
        assert (o.task_type, o.floor_plan, o.layout) == (entry.task_type, entry.floor_plan, entry.layout)
        assert o.end == "success" and o.goal_conditions[0] == o.goal_conditions[1] >= 1
        assert o.steps == o.expert_length > 0 and o.failures == 0
    m = oracle.overall
    assert (m.sr, m.gc, m.plw_sr, m.plw_gc, m.sr_all) == (1.0, 1.0, 1.0, 1.0, 1.0)


def test_random_fails_on_the_same_episodes(random_run, oracle):
    for o, expert in zip(random_run.outcomes, oracle.outcomes, strict=True):
        assert not o.success and o.end in ("stop", "max_failures", "max_steps")
        assert o.expert_length == expert.expert_length and o.instruction == expert.instruction
    assert random_run.overall.sr == 0.0 and random_run.overall.episodes == 2


def test_same_split_index_and_seed_give_the_same_outcome(random_run):
    job = EpisodeJob("random", "U+", INDICES[0], 3, json.dumps(_eval_kwargs(), sort_keys=True))
    assert run_job(job) == random_run.outcomes[0]


def test_ray_workers_give_the_same_outcomes_as_local_ones(random_run):
    pytest.importorskip("ray", reason="Ray is not installed (pip install 'luminous-sim[cluster]')")
    from luminous_sim.data import make_backend

    with make_backend("ray", workers=2) as backend:
        report = evaluate("random", "U+", INDICES, seed=3, backend=backend)
    assert report.to_dict() == random_run.to_dict()


class _Backwards:
    """A backend whose jobs finish in the reverse of the order they were given."""

    workers = 2

    def imap_unordered(self, fn, items):
        items = list(items)
        return ((item, fn(item)) for item in reversed(items))


def test_outcomes_come_back_in_the_order_of_the_episodes_whatever_finishes_first():
    assert list(map_ordered(str.upper, ["a", "b", "c"], _Backwards())) == ["A", "B", "C"]


def _eval_kwargs():
    from luminous_sim.env import EnvConfig
    from luminous_sim.eval import EVAL_ENV

    return EnvConfig.from_kwargs(dict(EVAL_ENV)).to_kwargs()


def test_an_entry_with_no_episode_is_a_reported_failure(monkeypatch):
    import luminous_sim.env.sources as sources

    def refuse(entry, worlds, verify_expert):
        raise EpisodeUnavailable(entry, "expert", "no Spatula anywhere")

    monkeypatch.setattr(sources, "split_spec", refuse)
    report = evaluate("random", "U+", [5])
    (o,) = report.outcomes
    assert (o.end, o.cause, o.detail, o.task_type) == ("unavailable", "expert", "no Spatula anywhere",
                                                        benchmark_entry("U+", 5).task_type)
    assert report.unavailable() == {"expert": 1}
    assert report.overall.sr is None and report.overall.sr_all == 0.0


def test_outputs_resume_and_refuse_another_evaluation(tmp_path, oracle):
    kept = oracle.outcomes[0].to_dict() | {"instruction": "read back, not replayed"}
    saved = tmp_path / "episodes" / f"U+-{INDICES[0]}.json"
    saved.parent.mkdir()
    saved.write_text(json.dumps(outcome_record(EpisodeOutcome.from_dict(kept))))
    again = evaluate("oracle", "U+", INDICES[:1], out_dir=tmp_path)   # an earlier run finished this one
    assert again.outcomes[0].to_dict() == kept
    assert json.loads((tmp_path / "run.json").read_text())["policy"] == "oracle"
    with pytest.raises(LuminousError, match="holds another evaluation"):
        evaluate("random", "U+", INDICES[:1], out_dir=tmp_path)
    paths = write_reports(again, tmp_path)
    report = json.loads(paths["json"].read_text())
    assert report["overall"]["sr"] == 1.0 and report["entries"] == 1 and report["episodes"][0] == kept
    assert paths["plot"].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and "| Examine |" in paths["table"].read_text()


def test_outcomes_are_written_as_they_finish(oracle_dir, oracle):
    for o in oracle.outcomes:
        assert json.loads((oracle_dir / "episodes" / f"U+-{o.index}.json").read_text()) == outcome_record(o)


@pytest.mark.parametrize("spec, message", [
    ("orcale", "expected oracle or random"),
    ("no_such_module_xyz:agent", "cannot import module"),
    ("json:no_such_name", "has no 'no_such_name'"),
    ("json:__name__", "not a callable"),
])
def test_bad_policy_specs_are_refused_clearly(spec, message):
    with pytest.raises(PolicyError, match=message):
        check_policy(spec)


def test_bad_split_or_arguments_are_refused_before_any_work():
    from luminous_sim.splits import SplitError

    with pytest.raises(SplitError, match=re.escape("unknown split 'V+'")):
        evaluate("random", "V+", 1)
    with pytest.raises(LuminousError, match="verify_expert"):
        evaluate("random", "U+", 1, env_kwargs={"verify_expert": False})
    with pytest.raises(LuminousError, match="at least one"):
        evaluate("random", "U+", [])


def test_an_agent_without_the_interface_is_refused():
    with pytest.raises(PolicyError, match="returned a str, which has no reset or act"):
        evaluate("builtins:str", "U+", [0])
    with pytest.raises(PolicyError, match="the factory raised TypeError"):
        evaluate("builtins:len", "U+", [0])
