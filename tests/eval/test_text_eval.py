"""`luminous eval --mode text`: text agents over a split's text games, in the agents' child process; won per
type in Table 4's rows; outputs written per episode and resumed; a bad agent is refused, a slow one timed
out, a crashing one stops the run."""

from __future__ import annotations

import json
import sys

import pytest

from luminous_sim.cli.main import main
from luminous_sim.errors import LuminousError
from luminous_sim.eval import AgentCrashed, AgentLimits, PolicyError, evaluate_text
from tests.conftest import UPLUS_BUILT

MODULE = "text_agents_for_tests"
AGENTS = '''
import time

def first(observation, admissible):
    return admissible[0]

def number(observation, admissible):
    return 7

def slow(observation, admissible):
    time.sleep(5)
    return "look"

def boom(observation, admissible):
    raise ValueError("boom")

seen = []

def remembers(observation, admissible):
    if observation.startswith("-= Welcome"):
        seen.clear()
    seen.append(observation)
    return "inventory" if len(seen) == 1 else "look"
'''


@pytest.fixture(scope="module")
def agents(tmp_path_factory):
    folder = tmp_path_factory.mktemp("text_agents")
    (folder / f"{MODULE}.py").write_text(AGENTS)
    sys.path.insert(0, str(folder))
    yield folder
    sys.path.remove(str(folder))


def test_the_expert_wins_every_type_and_the_table_has_table_4s_rows(tmp_path):
    report = evaluate_text("expert", "U+", UPLUS_BUILT, out_dir=tmp_path)
    assert [o.won for o in report.outcomes] == [True] * UPLUS_BUILT
    assert {o.end for o in report.outcomes} == {"won"}
    table = (tmp_path / "table.md").read_text()
    for label in ("Pick", "Cool", "Stack", "Heat", "Clean", "Examine", "Pick Two", "**All**"):
        assert f"| {label} |" in table
    assert "**1.000** (7/7)" in table
    saved = json.loads((tmp_path / "report.json").read_text())
    assert saved["per_type"]["all"] == {"episodes": UPLUS_BUILT, "won": UPLUS_BUILT, "won_rate": 1.0}
    assert len(list((tmp_path / "episodes").glob("U+-*.json"))) == UPLUS_BUILT


def test_a_run_resumes_from_its_episode_files_and_refuses_another_runs_folder(tmp_path):
    first = evaluate_text("random", "U+", 3, out_dir=tmp_path, seed=1)
    (tmp_path / "episodes" / "U+-1.json").write_text(json.dumps({**json.loads(
        (tmp_path / "episodes" / "U+-1.json").read_text()), "steps": 999}))
    again = evaluate_text("random", "U+", 3, out_dir=tmp_path, seed=1)
    assert [o.steps for o in again.outcomes] == [first.outcomes[0].steps, 999, first.outcomes[2].steps]
    with pytest.raises(LuminousError, match="another run"):
        evaluate_text("random", "U+", 3, out_dir=tmp_path, seed=2)


def test_a_users_agent_plays_in_its_own_process(agents, tmp_path):
    report = evaluate_text(f"{MODULE}:remembers", "U+", 2, out_dir=tmp_path)
    assert [o.end for o in report.outcomes] == ["step_limit", "step_limit"]
    assert all(o.steps == 50 and not o.won for o in report.outcomes)
    assert MODULE not in sys.modules, "the evaluation process never imports the agent's module"


def test_a_bad_slow_or_crashing_agent(agents, tmp_path):
    with pytest.raises(PolicyError, match="a text agent returns a command"):
        evaluate_text(f"{MODULE}:number", "U+", 1)
    slow = evaluate_text(f"{MODULE}:slow", "U+", 1, limits=AgentLimits(step_timeout=1.0))
    assert [o.end for o in slow.outcomes] == ["agent_timeout"]
    with pytest.raises(AgentCrashed, match="raised ValueError: boom"):
        evaluate_text(f"{MODULE}:boom", "U+", 1, out_dir=tmp_path)
    with pytest.raises(PolicyError, match="has no 'missing'"):
        evaluate_text(f"{MODULE}:missing", "U+", 1)


def test_the_command_line(agents, tmp_path, capsys):
    assert main(["eval", "--mode", "text", "--policy", "expert", "--split", "U+", "--episodes", "2",
                 "--out", str(tmp_path / "out")]) == 0
    assert "| **All** | **1.000** (2/2) |" in capsys.readouterr().out
    assert main(["eval", "--mode", "text", "--policy", "expert", "--out", str(tmp_path / "other")]) != 0
    assert "--mode text plays a frozen split's text games: give --split" in capsys.readouterr().err
