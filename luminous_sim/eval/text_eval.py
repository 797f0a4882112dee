"""Language-model agents on a split's text games (`luminous eval --mode text`): a text agent, the callable
`act(observation: str, admissible: list[str]) -> str` (`MODULE:CALLABLE`, in the agents' child process with
the same time and memory limits as embodied agents, `sandbox.AgentProcess`), plays each entry of a split in
`Luminous-Text-v0`; won per task type in Table 4's rows (text mode has no track: it is its own column).

The observation after a reset is the welcome, the room and the task ("-= Welcome to TextWorld, ALFRED! =-"
begins it: a new episode), then each command's feedback. Built-ins, run in this process: `expert` (the text
expert, `text.TextExpert`) and `random` (an admissible command drawn with the episode's seed).

Each episode's outcome is written to `OUT/episodes/<split>-<index>.json` when it ends (atomically), so an
interrupted run resumes in the same folder; `report.json` and `table.md` at the end."""

from __future__ import annotations

import json
import random
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from luminous_sim.eval.evaluator import episode_seed
from luminous_sim.eval.policies import PolicyError, TextAgentContext, check_policy
from luminous_sim.eval.report import TABLE4_ROWS
from luminous_sim.eval.sandbox import AgentCrashed, AgentLimits, AgentProcess, AgentTimeout
from luminous_sim.fileio import write_atomic

TEXT_BUILT_IN: tuple[str, ...] = ("expert", "random")
"""Text policies that run in the evaluation's process."""
RUN_FORMAT = "luminous-text-eval/1"


@dataclass(frozen=True)
class TextOutcome:
    """One episode: where it came from, whether it was won, in how many commands, and how it ended."""

    split: str
    index: int
    task_type: str
    episode_key: str
    won: bool
    steps: int
    end: str
    """`won`, `step_limit`, `agent_timeout` or `agent_stopped` (the agent returned no command)."""


@dataclass
class TextReport:
    """Every outcome of a run and what it was."""

    policy: str
    split: str
    seed: int
    outcomes: list[TextOutcome] = field(default_factory=list)

    def per_type(self) -> dict[str, dict[str, float | int]]:
        """Per task type (and `all`): episodes, won, and the share won."""
        out: dict[str, dict[str, float | int]] = {}
        for key in [t for t, _ in TABLE4_ROWS] + ["all"]:
            got = [o for o in self.outcomes if key in ("all", o.task_type)]
            if got:
                won = sum(o.won for o in got)
                out[key] = {"episodes": len(got), "won": won, "won_rate": round(won / len(got), 4)}
        return out

    def to_dict(self) -> dict[str, Any]:
        return {"format": RUN_FORMAT, "policy": self.policy, "split": self.split, "seed": self.seed,
                "per_type": self.per_type(), "outcomes": [asdict(o) for o in self.outcomes]}

    def markdown(self) -> str:
        """Table 4's rows with one column: the share of episodes won (and how many) in text mode."""
        rows = self.per_type()
        lines = [f"| Task type ({self.split}) | text: won ({self.policy}) |", "|---|---|"]
        for task_type, label in TABLE4_ROWS:
            r = rows.get(task_type)
            lines.append(f"| {label} | {r['won_rate']:.3f} ({r['won']}/{r['episodes']}) |" if r else f"| {label} | - |")
        typed = [rows[t]["won_rate"] for t, _ in TABLE4_ROWS if t in rows]
        if typed:
            lines.append(f"| Average | {sum(typed) / len(typed):.3f} |")
        if "all" in rows:
            a = rows["all"]
            lines.append(f"| **All** | **{a['won_rate']:.3f}** ({a['won']}/{a['episodes']}) |")
        return "\n".join(lines) + "\n"


class _ExpertAgent:
    """The text expert, replanned each episode (it reads the game, which a user's agent cannot)."""

    def __init__(self, env: Any):
        from luminous_sim.text import TextExpert

        self.env, self._make = env, TextExpert
        self.expert: Any = None

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.expert = self._make(self.env.game, self.env.episode.task.goal, dict(self.env.episode.task.names))

    def act(self, observation: str, info: dict[str, Any]) -> str | None:
        return self.expert.next_command()


class _RandomAgent:
    def __init__(self) -> None:
        self.rng = random.Random(0)

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.rng = random.Random(info["episode_seed"])

    def act(self, observation: str, info: dict[str, Any]) -> str:
        return self.rng.choice(info["admissible_commands"])


def _agent(policy: str, env: Any, split: str, limits: AgentLimits | None) -> Any:
    if policy == "expert":
        return _ExpertAgent(env)
    if policy == "random":
        return _RandomAgent()
    return AgentProcess(policy, TextAgentContext(split, env.config.max_steps), limits)


def play_text(env: Any, agent: Any, split: str, index: int, seed: int = 0) -> TextOutcome:
    """One entry played to its end (won, the step limit, or the agent out of time or commands)."""
    observation, info = env.reset(options={"split": split, "index": index})
    info = {**info, "episode_seed": episode_seed(seed, split, index)}
    key, task_type = info["episode_key"], info["task_type"]
    agent.reset(observation, info)
    steps, end = 0, "step_limit"
    while True:
        try:
            command = agent.act(observation, info)
        except AgentTimeout:
            end = "agent_timeout"
            break
        if command is None:
            end = "agent_stopped"
            break
        if not isinstance(command, str):
            raise PolicyError(f"a text agent returns a command (a str) such as 'go to countertop 1', got "
                              f"{type(command).__name__}")
        observation, _, terminated, truncated, info = env.step(command[:8192])
        steps += 1
        if terminated:
            end = "won"
            break
        if truncated:
            break
    return TextOutcome(split, index, task_type, key, bool(env.game.won), steps, end)


def evaluate_text(policy: str, split: str, episodes: int | Iterable[int], *, seed: int = 0, out_dir: Path | None = None,
                  limits: AgentLimits | None = None,
                  progress: Callable[[TextOutcome], None] | None = None) -> TextReport:
    """Play a text policy over entries of a split (`episodes`: the first N, or these indices).

    Raises:
        PolicyError: a bad spec, or an agent that returns something other than a command.
        AgentCrashed: the agent's process ended (episodes already played stay written).
        LuminousError: an output folder of another run (another policy, split or seed).
    """
    from luminous_sim.benchmark import benchmark_size
    from luminous_sim.env.text_env import TextEnv
    from luminous_sim.errors import LuminousError

    if policy not in TEXT_BUILT_IN:
        check_policy(policy, limits)
    indices = list(range(min(episodes, benchmark_size(split)))) if isinstance(episodes, int) else list(episodes)
    run = {"format": RUN_FORMAT, "policy": policy, "split": split, "seed": seed}
    if out_dir is not None:
        out_dir.mkdir(parents=True, exist_ok=True)
        claim = out_dir / "run.json"
        if claim.is_file() and json.loads(claim.read_text()) != run:
            raise LuminousError(f"{out_dir}: holds a text evaluation of another run ({claim.read_text().strip()}); "
                                "give another --out")
        write_atomic(claim, json.dumps(run, sort_keys=True) + "\n")
    env = TextEnv(split=split)
    report = TextReport(policy, split, seed)
    agent = None
    try:
        for index in indices:
            path = out_dir / "episodes" / f"{split}-{index}.json" if out_dir is not None else None
            if path is not None and path.is_file():
                outcome = TextOutcome(**json.loads(path.read_text()))
            else:
                agent = agent or _agent(policy, env, split, limits)
                try:
                    outcome = play_text(env, agent, split, index, seed)
                except AgentCrashed as exc:
                    raise exc.on(split, index) from None
                if path is not None:
                    write_atomic(path, json.dumps(asdict(outcome), sort_keys=True) + "\n")
            report.outcomes.append(outcome)
            if progress is not None:
                progress(outcome)
    finally:
        if isinstance(agent, AgentProcess):
            agent.close()
    if out_dir is not None:
        write_atomic(out_dir / "report.json", json.dumps(report.to_dict(), indent=1, sort_keys=True) + "\n")
        write_atomic(out_dir / "table.md", report.markdown())
    return report
