"""The expert from explicit inputs (an episode's scene, goal, set-up, a world source, the actions sent), with
no env: its first action is the proved plan's, it follows the plan while the agent does, and it replans from
where the agent stands after a deviation, in worlds from the source it was given."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.env.config import EnvConfig
from luminous_sim.env.episodes import drawing
from luminous_sim.env.expert import Expert
from luminous_sim.env.history import Sent
from luminous_sim.env.worlds import WorldPool
from luminous_sim.episodes import EpisodeSpec, draw_generated
from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose, World

CONFIG = EnvConfig(task_types=("pickup_object",), width=64, height=64)


class CountingSource:
    """A world source that counts what it hands out (a `WorldPool` underneath)."""

    def __init__(self, pool: WorldPool):
        self.pool, self.got, self.put_back = pool, 0, 0

    def get(self, scene: Scene, dirty: tuple[str, ...] = (), start: AgentPose | None = None) -> World:
        self.got += 1
        return self.pool.get(scene, dirty, start)

    def put(self, world: World) -> None:
        self.put_back += 1
        self.pool.put(world)


@pytest.fixture(scope="module")
def drawn():
    pool = WorldPool(CONFIG)
    episode, world = draw_generated(drawing(CONFIG), np.random.default_rng(0), pool)
    yield episode, world, pool
    world.close()
    pool.clear()


def send(world: World, history: list[Sent], api: dict) -> None:
    history.append(Sent(api, api, world.step(api).success))


def solved(episode: EpisodeSpec, world: World) -> bool:
    view = world.view()
    return episode.goal.scores(view, set(view.visible_objects())) == episode.goal.weights()


def test_the_expert_follows_its_proved_plan_without_planning(drawn):
    episode, _world, pool = drawn
    assert episode.expert is not None and len(episode.expert.actions) >= 2
    source = CountingSource(pool)
    expert = Expert.for_episode(episode, source)
    history: list[Sent] = []
    shadow = pool.get(episode.scene, episode.dirty, episode.start)  # stands in for the agent's world
    try:
        for expected in episode.expert.actions:
            api = expert.next_api(history)
            assert api == expected
            expert.suggested(len(history), api)
            send(shadow, history, api)
        assert expert.next_api(history) is None and solved(episode, shadow)
    finally:
        shadow.close()
    assert expert.replans == 0 and source.got == 0  # no shadow world: the plan was followed


def test_after_a_deviation_the_expert_replans_from_where_the_agent_stands(drawn):
    episode, _world, pool = drawn
    source = CountingSource(pool)
    expert = Expert(episode.scene, episode.goal, source, dirty=episode.dirty, start=episode.start)
    agent = pool.get(episode.scene, episode.dirty, episode.start)
    history: list[Sent] = []
    try:
        first = expert.next_api(history)  # no plan given: it plans on the first question
        assert expert.replans == 1 and first is not None
        for name in ("RotateLeft", "RotateLeft"):  # the agent turns round instead
            send(agent, history, {"action": name})
        for _ in range(len(episode.expert.actions) + 10):
            api = expert.next_api(history)
            if api is None:
                break
            expert.suggested(len(history), api)
            send(agent, history, api)
            assert history[-1].ok, api
        assert solved(episode, agent)
    finally:
        agent.close()
    assert expert.replans == 2 and source.got == source.put_back == 2  # one shadow world per plan, given back


def test_a_failed_suggested_action_makes_the_expert_replan(drawn):
    episode, _world, pool = drawn
    expert = Expert.for_episode(episode, pool)
    history: list[Sent] = []
    api = expert.next_api(history)
    expert.suggested(0, api)
    history.append(Sent(api, api, False))  # taken, but it failed: the world may not be where the plan says
    agent_api = expert.next_api(history)
    assert expert.replans == 1 and agent_api is not None
