"""The task families behaviour cloning is trained and evaluated on, at 64 px with object-slot targets:
`pickup` (pick up an object of a named type, in the layouts of LUMINOUS's evaluation splits; the default)
and `alfred` (the splits' own episodes: ALFRED's seven task types with ALFRED's limits, Table 4's setting).

Why `pickup` is the default and not ALFRED's seven types: a few hundred demonstrations of full ALFRED tasks (30-100
steps, two to four goal conditions, navigation across the room between them) give a cloned policy a
success rate near zero on both splits, which shows nothing. `pickup_object` keeps what the paper's finding
is about (the instruction names an object the agent must find in a room layout, and seen layouts differ
from unseen room structures) at a scale a CPU can learn: one goal condition, an expert of 10-30 steps.

Episode `i` of a split here is the frozen split's entry `i` (`luminous_sim.benchmark.benchmark_entry`) with
its task replaced: the same room structure and layout (`benchmark.layout_scene`, the layout every user of
the split plays), and a `pickup_object` goal drawn by the env from `reset(seed=entry.task_seed,
options={"scene": layout})`, so every machine plays the same episodes. An entry whose goal cannot be drawn is
an outcome (`end` "unavailable"), counted in the population, as in `luminous eval`.

Episode `i` of a split in the `alfred` family is the split's entry `i` itself (`reset(options={"split": ...,
"index": i})`), with ALFRED's limits (`EVAL_ENV`: 1000 steps, 10 failed actions), so a clone of it is
evaluated by `luminous_sim.eval.evaluate` exactly as any ALFRED agent (`ALFRED_ENV` over `EVAL_ENV`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from luminous_sim.benchmark import benchmark_entry, layout_scene
from luminous_sim.env import LuminousEnv
from luminous_sim.errors import InfeasibleSceneError, LuminousError
from luminous_sim.eval import EVAL_ENV, Agent, EpisodeOutcome, PolicyError, make_agent
from luminous_sim.splits import plus_split

FAMILY = "pickup_object"
PICKUP_ENV: dict[str, Any] = {
    "task_types": [FAMILY], "width": 64, "height": 64, "targets": "objects", "object_slots": 8,
    "max_steps": 200, "max_failures": 10, "verify_expert": True, "expert_in_info": False,
}
"""The env of the family: the small ids' image size and episode limit, object-slot targets (a clone
chooses among the objects in view rather than localising one in a 64 px image)."""


ALFRED_ENV: dict[str, Any] = {"width": 64, "height": 64, "targets": "objects", "object_slots": 8}
"""The `alfred` family's env over the evaluation's (`EVAL_ENV`: ALFRED's seven task types and limits): the image
size and object-slot targets of `PICKUP_ENV`, so one `BCPolicy` shape serves both families."""
FAMILIES: dict[str, dict[str, Any]] = {"pickup": PICKUP_ENV, "alfred": {**EVAL_ENV, **ALFRED_ENV}}
"""Each family's env options."""


def pickup_env(**overrides: Any) -> LuminousEnv:
    """A `LuminousEnv` of the family (`PICKUP_ENV` with overrides)."""
    return LuminousEnv(**{**PICKUP_ENV, **overrides})


def family_env(family: str, **overrides: Any) -> LuminousEnv:
    """A `LuminousEnv` of a family (`FAMILIES`) with overrides.

    Raises:
        LuminousError: an unknown family.
    """
    if family not in FAMILIES:
        raise LuminousError(f"unknown behaviour-cloning family {family!r}; choose one of {sorted(FAMILIES)}")
    return LuminousEnv(**{**FAMILIES[family], **overrides})


def where(split: str, index: int) -> dict[str, Any]:
    """The fields of an outcome that name the episode."""
    entry = benchmark_entry(split, index)
    return {"split": split, "index": index, "task_type": FAMILY, "floor_plan": entry.floor_plan,
            "layout": entry.layout}


class Unavailable(LuminousError):
    """A split entry with no episode of the family: `cause` is `layout` or `no_task` (pickup), or the env's
    `EpisodeUnavailable` cause (alfred: `expert`)."""

    def __init__(self, split: str, index: int, cause: str, detail: str, family: str = "pickup"):
        super().__init__(f"{split} {family} episode {index}: {detail}")
        self.cause, self.detail = cause, detail


def reset_episode(env: LuminousEnv, split: str, index: int) -> tuple[dict[str, Any], dict[str, Any]]:
    """Start episode `index` of `split` in `env` (a `pickup_env`); the first observation and info.

    In an env of the `alfred` family (any env whose task types are not the pickup family's) it is the split's entry
    itself.

    Raises:
        Unavailable: the layout or a goal the expert solves cannot be drawn.
    """
    if tuple(env.config.task_types) != (FAMILY,):
        from luminous_sim.env import EpisodeUnavailable

        try:
            return env.reset(options={"split": split, "index": index})
        except EpisodeUnavailable as exc:
            raise Unavailable(split, index, exc.cause, exc.detail, "alfred") from None
    entry = benchmark_entry(split, index)
    try:
        scene = layout_scene(entry.floor_plan, entry.room_type, entry.layout_seed)
    except InfeasibleSceneError as exc:
        raise Unavailable(split, index, "layout", str(exc)) from None
    try:
        return env.reset(seed=entry.task_seed, options={"scene": scene})
    except LuminousError as exc:
        raise Unavailable(split, index, "no_task", str(exc)) from None


def agent_seed(seed: int, split: str, index: int) -> int:
    """The seed of an agent's own randomness in one episode."""
    return int(np.random.SeedSequence([seed, plus_split(split).code, index, 15]).generate_state(1)[0])


def play_pickup(env: LuminousEnv, agent: Agent, split: str, index: int, seed: int = 0) -> EpisodeOutcome:
    """One pickup episode of a split played by `agent` to its end, as `luminous_sim.eval.play` plays one.

    Raises:
        PolicyError: the agent raised (the message names the episode).
    """
    named = where(split, index)
    try:
        obs, info = reset_episode(env, split, index)
    except Unavailable as exc:
        return EpisodeOutcome(**named, end="unavailable", cause=exc.cause, detail=exc.detail)
    assert env.episode is not None and env.episode.expert is not None, "the family's env proves the expert"
    steps, terminated, truncated = 0, False, False
    try:
        agent.reset(obs["instruction"], {**info, "episode_seed": agent_seed(seed, split, index)})
        while not (terminated or truncated):
            obs, _, terminated, truncated, info = env.step(agent.act(obs, info))
            steps += 1
    except Exception as exc:
        raise PolicyError(f"the agent raised on {split} pickup episode {index} at step {steps}: "
                          f"{type(exc).__name__}: {exc}") from exc
    finally:
        env.close()
    stopped = terminated and not info["success"]
    end = "success" if info["success"] else "stop" if stopped else (
        "max_failures" if info["failures"] >= env.config.max_failures else "max_steps")
    return EpisodeOutcome(**named, end=end, success=bool(info["success"]),
                          goal_conditions=tuple(info["goal_conditions"]),  # type: ignore[arg-type]
                          steps=steps - stopped, expert_length=len(env.episode.expert.actions),
                          failures=int(info["failures"]), instruction=str(obs["instruction"]))


def evaluate_pickup(policy: str, split: str, indices: list[int], *, seed: int = 0,
                    env_kwargs: dict[str, Any] | None = None) -> list[EpisodeOutcome]:
    """`policy` (`oracle`, `random` or `MODULE:CALLABLE`, as in `luminous eval`) on pickup episodes of a split,
    in this process; score the outcomes with `luminous_sim.eval.metrics`."""
    env = pickup_env(**(env_kwargs or {}))
    agent = make_agent(policy, env)
    try:
        return [play_pickup(env, agent, split, i, seed) for i in indices]
    finally:
        env.close()
