"""Pickling by replay: an env is saved as plain data (its config, random state, episode and the actions sent),
and restored by building the episode's world again and replaying those actions, since a PyBullet client
cannot be pickled. Navigation and the object-state layer are deterministic, so the replayed world is the
one that was saved."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import astuple
from typing import Any

from luminous_sim.env.history import Sent
from luminous_sim.env.kinds import goal_from_dict
from luminous_sim.env.shaping import RewardShaper
from luminous_sim.episodes import EpisodeSpec, ExpertPlan
from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose, World


def episode_data(episode: EpisodeSpec) -> dict[str, Any]:
    """An episode as plain data (`episode_from_data` reads it back)."""
    ep = episode
    return {"scene": ep.scene.to_json(), "goal": ep.goal.to_dict(), "dirty": list(ep.dirty),
            "expert": None if ep.expert is None else [list(ep.expert.actions), list(ep.expert.steps)],
            "redraws": ep.redraws, "start": None if ep.start is None else list(astuple(ep.start)), "key": ep.key}


def episode_from_data(data: dict[str, Any]) -> EpisodeSpec:
    """The episode of `episode_data` data."""
    plan = data["expert"]
    expert = None if plan is None else ExpertPlan(tuple(plan[0]), steps=tuple(plan[1]))
    start = None if data["start"] is None else AgentPose(*data["start"])
    return EpisodeSpec(Scene.from_json(data["scene"]), goal_from_dict(data["goal"]), tuple(data["dirty"]), expert,
                   data["redraws"], start, data.get("key", ""))


def history_data(history: Iterable[Sent]) -> list[tuple[Any, dict[str, Any], bool]]:
    """The actions sent, as plain data (`replay` reads it back)."""
    return [(s.given, s.api, s.ok) for s in history]


def replay(world: World, data: Iterable[tuple[Any, dict[str, Any], bool]], shaper: RewardShaper) -> list[Sent]:
    """Send the actions of `history_data` data to `world` (at the episode's start) again, the go-to reward state
    following them; the history they make."""
    history = []
    for given, api, ok in data:
        world.step(api)
        history.append(Sent(given, api, ok))
        shaper.replayed(world, api["action"], ok)
    return history
