"""The evaluation's tracks (issue 43): what an agent may observe and read. The privileged track adds depth,
segmentation and instance types; outside it those options are refused; in every track the agent's `info` is
`failure_code` and `error` only (and, at reset, `episode_seed` and `high_descs`), the objectId action form is
refused, and the track is recorded in run.json, report.json and table.md."""

from __future__ import annotations

import json
import sys

import pytest

from luminous_sim.cli import eval_cmd
from luminous_sim.errors import LuminousError
from luminous_sim.eval import (
    AGENT_INFO,
    TRACKS,
    AgentLimits,
    PolicyError,
    agent_info,
    evaluate,
    markdown_table,
    track_env,
    write_reports,
)
from tests.eval.test_cli import run

ENV = {"width": 64, "height": 64}
LIMITS = AgentLimits(step_timeout=30.0, memory_mb=4096)
AGENTS = '''
FORBIDDEN = ("task_type", "success", "goal_conditions", "subgoal", "expert_action", "failures")

class Spy:
    """Fails loudly if it is given more than the track allows; stops after two steps."""

    def __init__(self, depth):
        self.depth, self.steps = depth, 0

    def reset(self, instruction, info):
        self.steps = 0
        extra = set(info) - {"failure_code", "error", "episode_seed", "high_descs"}
        if extra:
            raise ValueError(f"reset info has {sorted(extra)}")

    def act(self, observation, info):
        if set(info) != {"failure_code", "error"}:
            raise ValueError(f"step info has {sorted(info)}")
        if ("depth" in observation) != self.depth or ("segmentation" in observation) != self.depth:
            raise ValueError(f"observation keys {sorted(observation)}")
        self.steps += 1
        return 1 if self.steps < 2 else {"action": "Stop"}

def rgb_spy(context):
    return Spy(False)

def privileged_spy(context):
    return Spy(True)

class ById:
    """Names its target by object id, the form no evaluated agent may use."""

    def reset(self, instruction, info):
        """Nothing to reset: it always asks for the same object."""

    def act(self, observation, info):
        return {"action": "PickupObject", "objectId": "Apple|+00.10|+00.90|+00.20"}

def by_id(context):
    return ById()
'''
MODULE = "track_agents_for_tests"


@pytest.fixture(scope="module")
def agents_dir(tmp_path_factory):
    folder = tmp_path_factory.mktemp("agents")
    (folder / f"{MODULE}.py").write_text(AGENTS)
    sys.path.insert(0, str(folder))
    yield folder
    sys.path.remove(str(folder))


def test_the_cli_tracks_are_the_evaluations():
    assert eval_cmd.TRACKS == TRACKS == ("rgb", "privileged")


@pytest.mark.parametrize("option", [{"depth": True}, {"segmentation": True}, {"instance_types": True},
                                    {"goal_mask": True}, {"targets": "objects"}])
def test_privileged_options_are_refused_outside_the_privileged_track(option):
    with pytest.raises(LuminousError, match="--track privileged"):
        track_env("rgb", option)
    assert track_env("privileged", option)["depth"] is True


def test_the_pose_and_the_experts_action_are_refused_in_every_track():
    for track in TRACKS:
        for name in ("pose", "expert_in_info"):
            with pytest.raises(LuminousError, match=f"{name}=true"):
                track_env(track, {name: True})
    with pytest.raises(LuminousError, match="track 'oracle'"):
        track_env("oracle", {})


def test_an_agent_reads_only_the_feedback():
    info = {"failure_code": "blocked", "error": "no", "success": True, "task_type": "x", "goal_conditions": (1, 2)}
    assert agent_info(info) == {"failure_code": "blocked", "error": "no"}
    assert set(agent_info(info, episode_seed=3)) == set(AGENT_INFO) | {"episode_seed"}


@pytest.mark.parametrize("track", TRACKS)
def test_each_track_gives_its_observations_and_the_feedback_only(agents_dir, tmp_path, track):
    spy = "privileged_spy" if track == "privileged" else "rgb_spy"
    report = evaluate(f"{MODULE}:{spy}", "U+", [2], env_kwargs=ENV, limits=LIMITS, out_dir=tmp_path, track=track)
    (outcome,) = report.outcomes
    assert outcome.end == "stop" and outcome.steps == 1
    assert report.track == track and report.env_kwargs["depth"] is (track == "privileged")
    assert json.loads((tmp_path / "run.json").read_text())["track"] == track
    paths = write_reports(report, tmp_path)
    assert json.loads(paths["json"].read_text())["track"] == track
    assert f"({track})" in paths["table"].read_text() and f"({track})" in markdown_table([report])
    with pytest.raises(LuminousError, match="holds another evaluation"):  # a track's folder resumes only as it
        evaluate(f"{MODULE}:{spy}", "U+", [2], env_kwargs=ENV, limits=LIMITS, out_dir=tmp_path,
                 track="rgb" if track == "privileged" else "privileged")


def test_the_object_id_form_is_refused(agents_dir):
    (outcome,) = evaluate(f"{MODULE}:by_id", "U+", [2], env_kwargs=ENV, limits=LIMITS).outcomes
    assert outcome.end == "invalid_action" and "object id" in outcome.detail


def test_the_modular_agent_in_the_rgb_track_names_the_privileged_track(tmp_path, capsys):
    with pytest.raises(PolicyError, match="--track privileged"):
        evaluate("luminous_sim.agents:modular", "U+", [2], env_kwargs=ENV, limits=LIMITS)
    code, _, err = run(["eval", "--policy", "luminous_sim.agents:modular", "--split", "U+", "--live", "--episodes",
                        "1", "--out", str(tmp_path / "out"), "--env", "width=64", "--env", "height=64"], capsys)
    assert code != 0 and "--track privileged" in err
    code, _, err = run(["eval", "--policy", "random", "--split", "U+", "--live", "--episodes", "1",
                        "--out", str(tmp_path / "out2"), "--env", "depth=true"], capsys)
    assert code != 0 and "--track privileged" in err
