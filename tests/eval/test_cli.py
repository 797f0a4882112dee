"""`luminous eval`: the worked example and a user's own module through MODULE:CALLABLE, the files it writes,
and clear one-line errors (exit 2) for a bad policy spec or split name."""

from __future__ import annotations

import json
import sys

import pytest

from luminous_sim.cli.eval_cmd import SPLITS
from luminous_sim.cli.main import main
from luminous_sim.splits import PLUS_SPLITS

USER_AGENT = '''
class Stopper:
    """Stops at once: the shortest possible episode."""

    def reset(self, instruction, info):
        self.instruction = instruction

    def act(self, observation, info):
        return {"action": "<<stop>>"}


def make(context):
    assert context.action_space.n == context.actions.n
    return Stopper()
'''


def run(argv, capsys):
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code
    out = capsys.readouterr()
    return code, out.out, out.err


def test_split_choices_are_the_splits():
    assert SPLITS == tuple(PLUS_SPLITS)


def test_the_worked_example_runs_through_the_cli_on_the_canonical_build(tmp_path, capsys):
    build = tmp_path / "canonical"
    code, out, err = run(["eval", "--policy", "luminous_sim.eval.examples:wanderer", "--split", "U+",
                          "--episodes", "1", "--build", str(build), "--out", str(tmp_path / "o")], capsys)
    assert code == 0, err
    assert (build / "manifest.jsonl").is_file() and "canonical U+ build: 1 trials" in err
    assert not list(build.rglob("*.jpg")), "the evaluation's build has no frames"
    report = json.loads((tmp_path / "o" / "report.json").read_text())
    assert report["policy"] == "luminous_sim.eval.examples:wanderer" and report["entries"] == 1
    (episode,) = report["episodes"]
    assert episode["end"] in ("stop", "max_failures") and 0 < episode["steps"] <= 41
    assert episode["trial"].startswith("U+/pick_and_place_simple-") and len(episode["episode_key"]) == 20
    assert "| **All** | **1/1** |" in out and "| Pick | 1/1 |" in (tmp_path / "o" / "table.md").read_text()
    assert (tmp_path / "o" / "metrics.png").stat().st_size > 0 and "U+    0 pick_and_place_simple" in err
    code, out, err = run(["eval", "--policy", "oracle", "--data", str(build), "--out", str(tmp_path / "d")], capsys)
    assert code == 0, err
    (episode,) = json.loads((tmp_path / "d" / "report.json").read_text())["episodes"]
    assert episode["success"] and episode["steps"] == episode["expert_length"]


def test_a_users_module_in_the_current_folder(tmp_path, capsys, monkeypatch):
    (tmp_path / "my_agent.py").write_text(USER_AGENT)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(sys, "path", [p for p in sys.path if p not in ("", str(tmp_path))])
    code, _out, err = run(["eval", "--policy", "my_agent:make", "--split", "U+", "--episodes", "1", "--live",
                           "--out", "results"], capsys)
    assert code == 0, err
    (episode,) = json.loads((tmp_path / "results" / "report.json").read_text())["episodes"]
    assert (episode["end"], episode["steps"], episode["success"]) == ("stop", 0, False)
    assert episode["goal_conditions"][1] >= 1 and episode["expert_length"] > 0


@pytest.mark.parametrize("argv, message", [
    (["--policy", "oracel"], "policy 'oracel': expected oracle or random, or MODULE:CALLABLE"),
    (["--policy", "no_such_agent_module:make"], "cannot import module 'no_such_agent_module'"),
    (["--policy", "luminous_sim.eval.examples:nothing"], "has no 'nothing'"),
    (["--split", "U"], "argument --split: invalid choice: 'U'"),
    (["--episodes", "0"], "argument --episodes: expected a whole number from 1 to 100000"),
    (["--address", "10.0.0.1:6379"], "--address 10.0.0.1:6379 is for the ray backend, not local"),
    (["--backend", "dask"], "argument --backend: invalid choice: 'dask'"),
    (["--live", "--build"], "--live plays the split's entries without a build"),
    (["--data", "nowhere"], "nowhere: no such file or folder; expected a dataset folder"),
])
def test_bad_specs_are_one_line_errors_with_exit_2(argv, message, tmp_path, capsys):
    args = {"--policy": "random", "--split": "U+", "--episodes": "1", "--out": str(tmp_path / "o")}
    if argv == ["--live", "--build"]:
        argv = ["--live", "", "--build", str(tmp_path / "b")]
    args.update(dict(zip(argv[::2], argv[1::2], strict=True)))
    if args.get("--data"):
        args.pop("--split")
    code, _out, err = run(["eval", *[x for kv in args.items() for x in (kv if kv[1] else kv[:1])]], capsys)
    assert code == 2 and message in err and "Traceback" not in err
    assert not (tmp_path / "o").exists()


def test_the_step_reader_follows_the_step_instructions_in_order():
    from luminous_sim.env import LuminousEnv
    from luminous_sim.eval import AgentContext
    from luminous_sim.eval.examples import WALK, step_action, step_reader

    env = LuminousEnv(width=64, height=64, task_types=["pick_and_place_simple"])
    agent = step_reader(AgentContext(env.action_space, env.observation_space, env.actions, env.config))
    env.close()
    assert step_action("Pick up the mug.") == "PickupObject" and step_action("Go left to the sink.") == ""
    agent.reset("put a mug in the sink", {"high_descs": ["Go to the counter.", "Pick up the mug.",
                                                          "Put the mug in the sink."], "episode_seed": 0})
    ok = {"failure_code": None}
    walked = [agent.act({}, ok) for _ in range(WALK + 1)]
    assert walked[:WALK] == [env.actions.index("MoveAhead")] * WALK
    tried = agent.act({}, ok)
    assert tried["action"] == "PickupObject" and tried["mask"]
    put = agent.act({}, ok)   # the pick up worked: on to the next step
    assert put["action"] == "PutObject"
    assert agent.act({}, ok) == {"action": "Stop"}   # the put worked and the steps ran out


def test_a_crashed_build_is_named_exits_non_zero_and_is_retried_on_the_next_run(tmp_path, capsys, monkeypatch):
    """A build job that crashed (missing data: an incomplete install) is the installation's failure, not the
    task's: eval prints its cause and exits 1, and neither the build nor the evaluation keeps it as a result."""
    import luminous_sim.episodes.split as split
    from luminous_sim.errors import RoomError

    def broken(entry):
        raise RoomError("no room 'FloorPlan10' in the room library")

    argv = ["eval", "--policy", "oracle", "--split", "U+", "--episodes", "1", "--build", str(tmp_path / "b"),
            "--out", str(tmp_path / "o")]
    with monkeypatch.context() as patch:
        patch.setattr(split, "entry_spec", broken)
        code, _out, err = run(argv, capsys)
    assert code == 1
    assert "unavailable: U+ 0 (build_crash): crash: RoomError: no room 'FloorPlan10'" in err
    assert "the population is incomplete" in err
    code, _out, err = run(argv, capsys)  # the install fixed: the same command builds and plays the entry
    assert code == 0, err
    assert "crashed on (or built as another episode) were done again: U+/000000" in err
    report = json.loads((tmp_path / "o" / "report.json").read_text())
    assert report["drawn"] == 1 and report["overall"]["sr"] == 1.0


def test_rebuild_builds_the_asked_entries_again(tmp_path, capsys):
    argv = ["eval", "--policy", "oracle", "--split", "U+", "--episodes", "1", "--build", str(tmp_path / "b"),
            "--out", str(tmp_path / "o")]
    assert run(argv, capsys)[0] == 0
    code, _out, err = run(argv + ["--rebuild"], capsys)
    assert code == 0, err
    assert "canonical U+ build: 1 trials" in err and "(1 built now)" in err
    code, _out, err = run(["eval", "--policy", "oracle", "--split", "U+", "--data", str(tmp_path / "b"), "--rebuild",
                           "--out", str(tmp_path / "p")], capsys)
    assert code == 2 and "leave out --build, --rebuild and --live" in err
