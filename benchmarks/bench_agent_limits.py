"""What the project's reference agents need from the agent sandbox's limits (`luminous_sim.eval.sandbox`).

Each reference agent plays a few U+ episodes live through `AgentProcess` (the child process `luminous eval`
runs a user's agent in), and this prints per agent: the time the child took to start (import and factory),
reset() and act() call times as the evaluation sees them (the round trip: pickling the observation, the
agent's work, the JSON reply) at p50, p99 and max, and the child's peak resident memory (VmHWM) and peak
address space (VmPeak, what `--agent-memory` limits: `RLIMIT_AS`). The defaults (`DEFAULT_STEP_TIMEOUT`,
`DEFAULT_AGENT_MEMORY_MB`) must stay at least 10x the largest p99 and peak address space printed here;
the last line says whether they do. Figures measured are in docs/benchmarks.md.

The agents: the built-in `random` (through a factory here, so that it runs in a child like a user's),
`luminous_sim.eval.examples:wanderer` and `:step_reader` at ALFRED's 300x300 camera, and
`luminous_sim.bc:bc_agent` (torch) in the env it is trained in (64 px, object slots), from an untrained
checkpoint of the real architecture written to a temporary folder (the same cost per step as a trained one).

    python benchmarks/bench_agent_limits.py --episodes 4
"""

from __future__ import annotations

import argparse
import io
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.env import LuminousEnv
from luminous_sim.eval import EVAL_ENV, AgentContext, AgentProcess, play
from luminous_sim.eval.policies import RandomAgent
from luminous_sim.eval.sandbox import DEFAULT_AGENT_MEMORY_MB, DEFAULT_STEP_TIMEOUT, AgentLimits


def random_agent(context: AgentContext) -> RandomAgent:
    """The built-in `random`, as a factory (so that it runs in a child process, as a user's agent does)."""
    return RandomAgent(context.actions.n)


class Timed:
    """An agent's calls, timed as the evaluation makes them."""

    def __init__(self, agent: AgentProcess):
        self.agent = agent
        self.resets: list[float] = []
        self.acts: list[float] = []

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        start = time.perf_counter()
        self.agent.reset(instruction, info)
        self.resets.append(time.perf_counter() - start)

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> Any:
        start = time.perf_counter()
        action = self.agent.act(observation, info)
        self.acts.append(time.perf_counter() - start)
        return action


def _status_kib(pid: int, key: str) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith(key + ":"):
            return int(line.split()[1])
    return 0


def _bc_checkpoint(folder: Path) -> dict[str, Any]:
    """An untrained `BCPolicy` checkpoint (the real architecture) and the env it is for."""
    import torch

    from luminous_sim.bc.demos import TOKENS
    from luminous_sim.bc.family import ALFRED_ENV
    from luminous_sim.bc.model import BCPolicy
    from luminous_sim.bc.train import FORMAT, shape_for

    shape = shape_for(int(ALFRED_ENV["object_slots"]))
    torch.manual_seed(0)
    model = BCPolicy(shape)
    meta = {"format": FORMAT, "shape": shape.to_dict(), "env": dict(ALFRED_ENV), "tokens": TOKENS, "seed": 0,
            "epochs": 0, "demos": 0, "samples": 0, "losses": [], "accuracy": 0.0}
    buf = io.BytesIO()
    torch.save({"meta": meta, "state_dict": model.state_dict()}, buf)
    path = folder / "bc.pt"
    path.write_bytes(buf.getvalue())
    os.environ["LUMINOUS_BC_CHECKPOINT"] = str(path)  # before the first child: the forkserver's environment
    return dict(ALFRED_ENV)


def measure(spec: str, env_kwargs: dict[str, Any], episodes: list[int]) -> dict[str, float]:
    env = LuminousEnv(**{**EVAL_ENV, **env_kwargs})
    context = AgentContext(env.action_space, env.observation_space, env.actions, env.config)
    limits = AgentLimits(step_timeout=600.0, memory_mb=DEFAULT_AGENT_MEMORY_MB)
    start = time.perf_counter()
    agent = AgentProcess(spec, context, limits)
    started = time.perf_counter() - start
    timed = Timed(agent)
    steps = 0
    for i in episodes:
        steps += play(env, timed, "U+", i).steps
        env.close()
    assert agent.pid is not None
    rss, vm = _status_kib(agent.pid, "VmHWM"), _status_kib(agent.pid, "VmPeak")
    agent.close()
    acts = np.array(timed.acts) * 1000
    resets = np.array(timed.resets) * 1000
    return {"start_s": started, "steps": steps, "act_p50_ms": float(np.percentile(acts, 50)),
            "act_p99_ms": float(np.percentile(acts, 99)), "act_max_ms": float(acts.max()),
            "reset_p99_ms": float(np.percentile(resets, 99)), "rss_mb": rss / 1024, "vm_mb": vm / 1024}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--episodes", type=int, default=4, help="U+ entries 0 .. N-1 per agent (default 4)")
    args = parser.parse_args()
    sys.path.insert(0, str(Path(__file__).resolve().parent))  # this module, for `random_agent` in the child
    episodes = list(range(args.episodes))
    with tempfile.TemporaryDirectory() as tmp:
        bc_env = _bc_checkpoint(Path(tmp))
        agents = [("random", "bench_agent_limits:random_agent", {}),
                  ("wanderer", "luminous_sim.eval.examples:wanderer", {}),
                  ("step_reader", "luminous_sim.eval.examples:step_reader", {}),
                  ("bc_agent", "luminous_sim.bc:bc_agent", bc_env)]
        print(f"{'agent':<12} {'start s':>8} {'steps':>6} {'act p50 ms':>11} {'act p99 ms':>11} {'act max ms':>11} "
              f"{'reset p99 ms':>13} {'peak RSS MB':>12} {'peak VM MB':>11}")
        worst_p99, worst_vm = 0.0, 0.0
        for name, spec, env_kwargs in agents:
            m = measure(spec, env_kwargs, episodes)
            worst_p99 = max(worst_p99, m["act_p99_ms"], m["reset_p99_ms"])
            worst_vm = max(worst_vm, m["vm_mb"], m["rss_mb"])
            print(f"{name:<12} {m['start_s']:8.2f} {m['steps']:6d} {m['act_p50_ms']:11.2f} {m['act_p99_ms']:11.2f} "
                  f"{m['act_max_ms']:11.2f} {m['reset_p99_ms']:13.2f} {m['rss_mb']:12.0f} {m['vm_mb']:11.0f}",
                  flush=True)
    print(f"defaults: step timeout {DEFAULT_STEP_TIMEOUT:g} s = {DEFAULT_STEP_TIMEOUT * 1000 / worst_p99:.0f}x the "
          f"largest p99 ({worst_p99:.1f} ms); memory {DEFAULT_AGENT_MEMORY_MB} MB = "
          f"{DEFAULT_AGENT_MEMORY_MB / worst_vm:.1f}x the largest peak ({worst_vm:.0f} MB address space)")


if __name__ == "__main__":
    main()
