"""A user's agent runs in a child process with limits (issue: hostile agents): a step over the time limit ends
its episode as `agent_timeout` and the run goes on; `sys.exit`, `os._exit`, a signal, memory past the limit or
an exception stop the run with the cause named and exit 1, the episodes finished before kept (and resumed),
on the local backend and on Ray. The evaluation process never imports the agent's module."""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest

from luminous_sim.cli import eval_cmd
from luminous_sim.env import LuminousEnv
from luminous_sim.eval import (
    AgentContext,
    AgentCrashed,
    AgentLimits,
    AgentProcess,
    AgentTimeout,
    PolicyError,
    evaluate,
    sandbox,
)
from luminous_sim.eval.metrics import AGENT_FAULT, ENDS
from tests.eval.test_cli import run

EPISODES = [9, 23]
"""Two U+ entries that play fast (look_at_obj_in_light)."""
ENV = {"width": 64, "height": 64}
LIMITS = AgentLimits(step_timeout=1.0, memory_mb=2048)
AGENTS = '''
import os, signal, sys, time

class Hostile:
    """Plays two steps and stops in its first episode; misbehaves at step 2 of the next ("sleep": at step 2
    of every episode)."""

    def __init__(self, mode):
        self.mode, self.episodes, self.steps = mode, 0, 0

    def reset(self, instruction, info):
        self.episodes, self.steps = self.episodes + 1, 0
        if self.mode == "sleep_reset":
            time.sleep(3600)

    def act(self, observation, info):
        self.steps += 1
        if self.steps == 2 and (self.episodes >= 2 or self.mode == "sleep"):
            if self.mode == "sleep":
                time.sleep(3600)
            if self.mode == "exit":
                sys.exit(0)
            if self.mode == "os_exit":
                os._exit(3)
            if self.mode == "signal":
                os.kill(os.getpid(), signal.SIGKILL)
            if self.mode == "memory":
                return len(bytearray(64 * 2**30))
            if self.mode == "raise":
                raise ValueError("boom")
        return 0 if self.steps < 3 else {"action": "Stop"}

def make(mode):
    return lambda context: Hostile(mode)

sleep, sleep_reset, exit, os_exit, signal_, memory, raise_ = (
    make(m) for m in ("sleep", "sleep_reset", "exit", "os_exit", "signal", "memory", "raise"))

class Odd:
    """Returns numpy and odd actions: a numpy index, a mask as an array, an object of its own."""

    def reset(self, instruction, info):
        self.steps = 0

    def act(self, observation, info):
        import numpy as np
        self.steps += 1
        if self.steps == 1:
            return np.int64(1)
        if self.steps == 2:
            return {"action": "PickupObject", "mask": np.zeros((64, 64), bool)}
        return object()

def odd(context):
    return Odd()
'''
CRASHES = {  # the agent's callable: the cause, and what the message says
    "exit": ("exit", "the agent called sys.exit(0) during act() on U+ episode 23 at step 2"),
    "os_exit": ("exit", "the agent exited with status 3 during act() on U+ episode 23 at step 2"),
    "signal_": ("signal", "the agent process was killed by SIGKILL"),
    "memory": ("memory", "the agent exceeded its memory limit of 2048 MB (--agent-memory; MemoryError"),
    "raise_": ("raised", "the agent raised ValueError: boom during act() on U+ episode 23 at step 2"),
}
MODULE = "hostile_agents_for_tests"


@pytest.fixture(scope="module")
def agents_dir(tmp_path_factory):
    folder = tmp_path_factory.mktemp("agents")
    (folder / f"{MODULE}.py").write_text(AGENTS)
    (folder / "exits_on_import.py").write_text("import sys\nsys.exit(0)\ndef make(context):\n    pass\n")
    sys.path.insert(0, str(folder))
    yield folder
    sys.path.remove(str(folder))


def test_the_cli_defaults_are_the_sandboxs():
    assert (eval_cmd.DEFAULT_STEP_TIMEOUT, eval_cmd.DEFAULT_AGENT_MEMORY_MB, eval_cmd.MIN_AGENT_MEMORY_MB) == (
        sandbox.DEFAULT_STEP_TIMEOUT, sandbox.DEFAULT_AGENT_MEMORY_MB, sandbox.MIN_AGENT_MEMORY_MB)
    assert "agent_timeout" in ENDS


def test_a_step_over_the_limit_ends_its_episode_as_agent_timeout_and_the_run_goes_on(agents_dir, tmp_path):
    report = evaluate(f"{MODULE}:sleep", "U+", EPISODES, env_kwargs=ENV, limits=LIMITS, out_dir=tmp_path)
    assert [o.end for o in report.outcomes] == ["agent_timeout", "agent_timeout"]
    for o in report.outcomes:
        assert o.cause == AGENT_FAULT and not o.success and o.steps == 1
        assert o.detail == "step 2: act() did not return within 1 s (the step limit, --step-timeout)"
        assert json.loads((tmp_path / "episodes" / f"U+-{o.index}.json").read_text())["end"] == "agent_timeout"
    assert report.overall.sr == 0.0 and report.overall.gc == 0.0 and report.overall.episodes == 2
    assert MODULE not in sys.modules, "the evaluation process never imports the agent's module"


def test_a_reset_over_the_limit_is_a_timeout_too(agents_dir):
    (o,) = evaluate(f"{MODULE}:sleep_reset", "U+", EPISODES[:1], env_kwargs=ENV, limits=LIMITS).outcomes
    assert (o.end, o.steps, o.detail) == ("agent_timeout", 0, "at reset: reset() did not return within 1 s (the "
                                          "step limit, --step-timeout)")


@pytest.mark.parametrize("name", list(CRASHES))
def test_a_crash_is_named_and_keeps_the_finished_episodes(name, agents_dir, tmp_path):
    cause, message = CRASHES[name]
    with pytest.raises(AgentCrashed) as caught:
        evaluate(f"{MODULE}:{name}", "U+", EPISODES, env_kwargs=ENV, limits=LIMITS, out_dir=tmp_path)
    assert caught.value.cause == cause and message in str(caught.value), str(caught.value)
    assert str(caught.value).endswith("on U+ episode 23 at step 2")
    assert sorted(p.name for p in (tmp_path / "episodes").iterdir()) == ["U+-9.json"]
    assert json.loads((tmp_path / "episodes" / "U+-9.json").read_text())["end"] == "stop"


@pytest.mark.timeout(300)
def test_a_crash_in_a_local_worker_process_is_named_and_its_workers_exit(agents_dir, tmp_path):
    """Two worker processes, each with its agent's child: the crash comes back named, and the workers exit (an
    idle agent child is killed before multiprocessing joins a worker's children)."""
    with pytest.raises(AgentCrashed, match="the agent exited with status 3 during act") as caught:
        evaluate(f"{MODULE}:os_exit", "U+", [9, 23, 30], env_kwargs=ENV, limits=LIMITS, workers=2, out_dir=tmp_path)
    assert caught.value.cause == "exit" and str(caught.value).endswith("at step 2")
    assert sorted(p.name for p in (tmp_path / "episodes").iterdir()) == ["U+-23.json", "U+-9.json"]


def test_the_cli_exits_1_with_the_cause_and_resumes(agents_dir, tmp_path, capsys):
    argv = ["eval", "--policy", f"{MODULE}:os_exit", "--split", "U+", "--live", "--episodes", "2", "--out",
            str(tmp_path / "o"), "--env", "width=64", "--env", "height=64", "--step-timeout", "1"]
    code, _out, err = run(argv, capsys)
    assert code == 1
    assert "luminous eval: error: the agent exited with status 3 during act() on U+ episode 1 at step 2" in err
    assert "1 finished episode kept in" in err and not (tmp_path / "o" / "report.json").exists()
    kept = (tmp_path / "o" / "episodes" / "U+-0.json").read_text()
    code, _out, err = run(argv, capsys)  # resumes: episode 0 is read back; episode 1 is a fresh child's first
    assert code == 0, err
    assert (tmp_path / "o" / "episodes" / "U+-0.json").read_text() == kept
    report = json.loads((tmp_path / "o" / "report.json").read_text())
    assert [e["end"] for e in report["episodes"]] == ["stop", "stop"]
    code, _out, err = run(["eval", "--policy", "exits_on_import:make", "--split", "U+", "--live", "--episodes",
                               "1", "--out", str(tmp_path / "x")], capsys)
    assert code == 1 and "the agent called sys.exit(0) while starting (importing exits_on_import" in err


@pytest.mark.parametrize("argv, message", [
    (["--step-timeout", "0"], "argument --step-timeout: expected a number of seconds above 0 and at most 86400"),
    (["--step-timeout", "inf"], "argument --step-timeout: expected a number of seconds above 0"),
    (["--agent-memory", "100"], "argument --agent-memory: expected a whole number from 1024 to 1048576"),
])
def test_bad_limits_are_refused(argv, message, tmp_path, capsys):
    code, _out, err = run(["eval", "--policy", "random", "--split", "U+", "--live", "--out", str(tmp_path / "o"),
                               *argv], capsys)
    assert code == 2 and message in err and not (tmp_path / "o").exists()


def test_limits_are_checked():
    with pytest.raises(PolicyError, match="step_timeout must be a positive number"):
        AgentLimits(step_timeout=-1)
    with pytest.raises(PolicyError, match="memory_mb must be a whole number of MiB, at least 1024"):
        AgentLimits(memory_mb=10)


def test_actions_cross_as_data_and_anything_else_is_not_an_action(agents_dir):
    (o,) = evaluate(f"{MODULE}:odd", "U+", EPISODES[:1], env_kwargs=ENV, limits=LIMITS).outcomes
    assert o.end == "invalid_action" and o.steps == 3 and o.failures == 1  # the empty mask: a failed action
    assert o.detail.startswith("step 3: the agent returned <object object at ")
    mask = np.arange(6, dtype=np.uint8).reshape(2, 3)
    back = sandbox._decode(json.loads(json.dumps(sandbox.encode({"mask": mask, "point": (1, np.float32(2.5))}))))
    assert np.array_equal(back["mask"], mask) and back["mask"].dtype == np.uint8 and back["point"] == [1, 2.5]
    assert isinstance(sandbox._decode({"__ndarray__": ["|O", [1], ""]}), sandbox.Unsent)


def test_the_child_gets_a_copy_of_the_context_and_restarts_after_a_timeout(agents_dir):
    env = LuminousEnv(**ENV)
    context = AgentContext(env.action_space, env.observation_space, env.actions, env.config)
    agent = AgentProcess(f"{MODULE}:sleep", context, LIMITS)
    first = agent.pid
    agent.reset("go", {"episode_seed": 1})
    assert agent.act({"rgb": np.zeros((64, 64, 3), np.uint8)}, {}) == 0
    with pytest.raises(AgentTimeout):
        agent.act({}, {})
    assert agent.pid is None
    agent.reset("go", {"episode_seed": 2})
    assert agent.pid not in (None, first) and agent.starts == 2 and agent.act({}, {}) == 0
    agent.close()
    env.close()


@pytest.fixture(scope="module")
def ray_backend(agents_dir):
    pytest.importorskip("ray", reason="Ray is not installed (pip install 'luminous-sim[cluster]')")
    from luminous_sim.data import make_backend

    with pytest.MonkeyPatch.context() as patch:  # the local cluster's workers import the agents from here
        patch.setenv("PYTHONPATH", str(agents_dir))
        with make_backend("ray", workers=1) as backend:
            yield backend


def test_on_ray_a_timeout_ends_the_episode_and_each_crash_is_named(ray_backend, tmp_path):
    report = evaluate(f"{MODULE}:sleep", "U+", EPISODES, env_kwargs=ENV, limits=LIMITS, backend=ray_backend)
    assert [o.end for o in report.outcomes] == ["agent_timeout", "agent_timeout"]
    for name, (cause, message) in CRASHES.items():
        out = tmp_path / name
        with pytest.raises(AgentCrashed) as caught:
            evaluate(f"{MODULE}:{name}", "U+", EPISODES, env_kwargs=ENV, limits=LIMITS, backend=ray_backend,
                     out_dir=out)
        assert caught.value.cause == cause and message in str(caught.value), (name, str(caught.value))
        assert [p.name for p in (out / "episodes").iterdir()] == ["U+-9.json"]


def test_on_ray_the_cli_exits_1_with_the_cause(ray_backend, agents_dir, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(agents_dir)
    monkeypatch.setenv("PYTHONPATH", str(agents_dir))  # the command adds the current folder to it
    code, _out, err = run(["eval", "--policy", f"{MODULE}:exit", "--split", "U+", "--live", "--episodes", "2",
                               "--backend", "ray", "--out", str(tmp_path / "o"), "--env", "width=64", "--env",
                               "height=64"], capsys)
    assert code == 1, err
    assert "luminous eval: error: the agent called sys.exit(0) during act() on U+ episode 1 at step 2" in err
    assert "Traceback" not in err and [p.name for p in (tmp_path / "o" / "episodes").iterdir()] == ["U+-0.json"]


def test_a_resume_with_other_agent_limits_is_refused(tmp_path, capsys):
    """The limits decide which episodes end as agent_timeout: run.json records them and a resume must match."""
    argv = ["eval", "--policy", "random", "--split", "U+", "--episodes", "1", "--live", "--out", str(tmp_path / "o")]
    code, _out, err = run(argv, capsys)
    assert code == 0, err
    assert json.loads((tmp_path / "o" / "run.json").read_text())["limits"]["step_timeout"] == 10.0
    code, _out, err = run(argv + ["--step-timeout", "3"], capsys)
    assert code == 2 and "another evaluation" in err
