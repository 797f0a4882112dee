"""The modular agent's parts (camera, own pose, map, A*, subgoals, priors) and the whole agent on real episodes:
it maps what it sees, solves an entry, refuses an env without its observations, and acts only on what it is
given (the observation-replay test)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from luminous_sim.agents.camera import Intrinsics, unproject
from luminous_sim.agents.modular_agent import NEEDS, ModularAgent, TrackError, modular
from luminous_sim.agents.navigation import plan_path
from luminous_sim.agents.own_pose import OwnPose
from luminous_sim.agents.priors import PRIORS_FILE, SearchPriors, default_priors
from luminous_sim.agents.semantic_map import SemanticMap
from luminous_sim.agents.subgoals import subgoals
from luminous_sim.env import EnvConfig, LuminousEnv
from luminous_sim.errors import LuminousError
from luminous_sim.eval.evaluator import EVAL_ENV, play
from luminous_sim.eval.tracks import agent_info
from luminous_sim.world.client import body_aabb

SIDE = 96


def _env(side: int = SIDE) -> LuminousEnv:
    return LuminousEnv(split="S+", **{**EVAL_ENV, "width": side, "height": side}, depth=True, segmentation=True,
                       instance_types=True)


@pytest.fixture(scope="module")
def first() -> tuple[LuminousEnv, dict, dict]:
    env = _env()
    obs, info = env.reset(seed=0, options={"split": "S+", "index": 3})
    yield env, obs, info
    env.close()


def test_unprojected_pixels_lie_on_what_they_show(first):
    env, obs, _ = first
    world = env.world
    pose = world.agent
    depth, seg = obs["depth"][..., 0], obs["segmentation"]
    rows, cols = np.nonzero(depth < 10)
    pts = unproject(depth[rows, cols], rows, cols, Intrinsics(SIDE, SIDE), pose.x, pose.y, pose.rotation,
                    pose.horizon)
    checked = 0
    for body, oid in world.body_to_object().items():
        mine = seg[rows, cols] == body
        if mine.sum() < 20:
            continue
        lo, hi = body_aabb(world.client, body)
        inside = np.all((pts[mine] >= np.array(lo) - 0.03) & (pts[mine] <= np.array(hi) + 0.03), axis=1)
        assert inside.mean() > 0.6, oid
        checked += 1
    assert checked >= 3
    assert abs(np.percentile(pts[:, 2], 1)) < 0.05  # the floor is at 0


def test_instance_types_name_each_visible_body(first):
    env, obs, _ = first
    from luminous_sim.vocab import ALL_TYPES

    state = env.world.view().state
    for body, oid in env.world.body_to_object().items():
        pixels = obs["segmentation"] == body
        if pixels.any() and oid in state.objects:
            want = ALL_TYPES.index(state.objects[oid].object_type) + 1
            assert set(np.unique(obs["instance_types"][pixels])) == {want}
    assert (obs["instance_types"][obs["segmentation"] < 0] == 0).all()


def test_own_pose_follows_successful_moves():
    pose = OwnPose()
    for name in ("MoveAhead", "RotateRight", "MoveAhead", "MoveAhead", "LookDown", "RotateLeft", "RotateLeft"):
        pose = pose.after(name)
    assert pose == OwnPose(node=(2, 1), heading=3, horizon=45)
    assert OwnPose(horizon=60).after("LookDown").horizon == 60


def test_astar_goes_around_what_the_map_blocks():
    m = SemanticMap(Intrinsics(SIDE, SIDE))
    m.visited.update({(x, y) for x in range(-3, 4) for y in range(-1, 6)})
    wall = {(x, 2) for x in range(-3, 3)}
    m.visited -= wall
    m.obstacle[:, :] = 0
    for x, y in wall:
        cx, cy = m.cell(np.array([x * 0.25]), np.array([y * 0.25]))
        m.obstacle[cx[0], cy[0]] = 5
    m.frame += 1
    path = plan_path(m, ((0, 0), 0), [((0, 4), 0)])
    assert path is not None
    pose = OwnPose()
    for name in path:
        pose = pose.after(name)
        assert pose.node not in wall
    assert pose.node == (0, 4)
    m.blocked_moves.add(((0, 0), 0))
    assert plan_path(m, ((0, 0), 0), [((0, 1), 0)])[0] != "MoveAhead"


def test_subgoals_follow_alfred_plans():
    heat = subgoals("pick_heat_then_place_in_recep", {"object_target": "Egg", "parent_target": "Fridge"})
    assert [s.action for s in heat] == ["PickupObject", "OpenObject", "PutObject", "CloseObject", "ToggleObjectOn",
                                        "ToggleObjectOff", "OpenObject", "PickupObject", "CloseObject", "OpenObject",
                                        "PutObject"]
    sliced = subgoals("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Plate",
                                                "object_sliced": True})
    assert [s.action for s in sliced][:3] == ["PickupObject", "SliceObject", "PutObject"]
    assert sliced[3].types == ("AppleSliced",)
    two = subgoals("pick_two_obj_and_place", {"object_target": "Pen", "parent_target": "Box"})
    assert [s.role for s in two if s.action == "PickupObject"] == ["object", "other"]


def test_priors_are_counts_from_generated_scenes():
    priors = default_priors()
    assert PRIORS_FILE.exists() and len(priors.counts) > 20
    assert priors.chance("Apple", "Fridge") > 0
    for obj in priors.counts:
        assert sum(priors.chance(obj, r) for r in priors.counts[obj]) == pytest.approx(1.0)


def test_a_damaged_priors_file_is_named(tmp_path):
    bad = tmp_path / "p.json"
    bad.write_text(json.dumps({"counts": {"Apple": {"Fridge": "many"}}}))
    with pytest.raises(LuminousError, match="p.json"):
        SearchPriors.load(bad)


def test_the_factory_refuses_an_env_without_its_observations():
    class Context:
        config = EnvConfig(**EVAL_ENV)

    with pytest.raises(TrackError, match="--track privileged"):
        modular(Context())
    Context.config = EnvConfig(**EVAL_ENV, **{k: True for k in NEEDS})
    assert isinstance(modular(Context()), ModularAgent)


def _comparable(action: dict) -> tuple:
    """An action as a value `==` can compare (its mask, an array, as bytes)."""
    mask = action.get("mask")
    return action["action"], None if mask is None else (mask.shape, np.packbits(mask).tobytes())


def test_its_actions_depend_on_its_observations_only(first):
    """Episode A's observations, replayed to a fresh agent while the env holds episode B, give A's actions."""
    env = _env()
    try:
        obs, info = env.reset(seed=0, options={"split": "S+", "index": 2})
        steps = [s for s in obs["high_descs"].split("\n") if s]
        agent = ModularAgent(SIDE, SIDE)
        agent.reset(obs["instruction"], agent_info(info, episode_seed=1, high_descs=steps))
        seen, actions = [], []
        for _ in range(30):
            action = agent.act(obs, agent_info(info))
            seen.append((obs, agent_info(info)))
            actions.append(action)
            if action["action"] == "Stop":
                break
            obs, _, done, cut, info = env.step(action)
            if done or cut:
                break
        env.reset(seed=0, options={"split": "S+", "index": 5})  # the env now holds another episode
        fresh = ModularAgent(SIDE, SIDE)
        fresh.reset(seen[0][0]["instruction"], agent_info({}, episode_seed=1, high_descs=steps))
        assert [_comparable(fresh.act(o, i)) for o, i in seen] == [_comparable(a) for a in actions]
    finally:
        env.close()


def test_luminous_eval_runs_it_in_its_own_process_in_the_privileged_track():
    """`luminous eval --policy luminous_sim.agents:modular --track privileged` (the agent in the sandbox's child
    process) plays an entry as the agent does in this process."""
    from luminous_sim.eval import evaluate

    (outcome,) = evaluate("luminous_sim.agents:modular", "S+", [2], track="privileged").outcomes
    env = _env(300)
    try:
        here = play(env, ModularAgent(300, 300), "S+", 2)
    finally:
        env.close()
    assert (outcome.success, outcome.steps, outcome.goal_conditions) == (here.success, here.steps,
                                                                         here.goal_conditions)
    assert outcome.success


def test_the_priors_episodes_are_in_no_split_room():
    """The priors are counted in CSSG's own rooms: the script's first episodes pass its check, and a layout of a
    frozen split (in an ALFRED floor plan, as every split is) is refused."""
    from luminous_sim.benchmark import layout_scene, split_layouts
    from tests.conftest import load_script

    for script in load_script("scripts/learn_search_priors.py"):
        assert script.count_parents(2, 1_000_000)  # each episode's scene checked on the way
        layout = split_layouts("U+")[0]
        with pytest.raises(ValueError, match=layout.floor_plan):
            script.check_outside_splits(layout_scene(layout.floor_plan, layout.room_type, layout.layout_seed))


@pytest.mark.slow
def test_the_shipped_priors_are_what_the_script_counts():
    """`scripts/learn_search_priors.py --episodes 60 --seed 1000000` remakes the shipped file (about 45 s)."""
    from tests.conftest import load_script

    for script in load_script("scripts/learn_search_priors.py"):
        assert SearchPriors(script.count_parents(60, 1_000_000)).to_json() == PRIORS_FILE.read_text()
