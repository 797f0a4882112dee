"""`LuminousEnv`: ALFRED-style household tasks in generated rooms, as a Gymnasium environment.

Observations (a `Dict`): `rgb` (H, W, 3) uint8; `instruction` (`Text`: the goal directive, and with
`step_instructions` the expert plan's step-by-step instructions after it); with `high_descs`, `high_descs`
(`Text`: the step-by-step instructions, one per line, as ALFRED's `high_descs`; the same string every step
of an episode); with `objects` targets,
`objects` (the type of the object in each slot, as `inventory` gives it); optionally
`depth` (H, W, 1) float32 metres, `segmentation` (H, W) int32 instance ids (PyBullet bodies, -1 for none),
`goal_mask` (H, W, 1) uint8 (255 on the goal type's pixels; `luminous_sim.env.goal_mask`),
`pose` (x, y metres, yaw and horizon degrees) and `inventory` (the held object's type, an index into
`luminous_sim.vocab.ALL_TYPES` plus one; 0 for nothing).

Actions: a `Discrete` index (see `luminous_sim.env.actions`: navigation, Stop, each interaction on a k x k
grid of image points, or with `targets="objects"` on visible-object slots), or the full ALFRED form for
ALFRED-style agents, a dict::

    {"action": "PickupObject", "mask": rle}            # or "point": [x, y], or "objectId": id
    {"action": "PutObject", "mask": rle}               # puts the held object on what the mask shows
    {"action": "MoveAhead"}   {"action": "Stop"}       # "<<stop>>" stops too

An invalid action (a failed one, an index outside the space, a malformed dict) costs a step and counts as
a failure; it never raises. `info["failure_code"]` says why (a `FailureCode` value, None on success).

Episodes end (`terminated`) on success or Stop, and are cut off (`truncated`) after `max_steps` steps or
`max_failures` failed actions; `step` after that raises `ResetNeeded` (call `reset`), as before the first
`reset`. A goal that counts only at Stop (`objectnav`) succeeds only on the Stop step. `info`: `success`,
`goal_conditions` (met, total), `subgoal` (the first
condition not yet met), `task_type`, `failures`, `failure_code`, `error`, and with `expert_in_info` the
expert's next action (`expert_action`, in this env's action form). For a goal scored the navigation way
(`objectnav`, `objectnav_pickup`; see `luminous_sim.env.navscore`), the reset's `info` has
`shortest_path_length`, `start_distance`, `target_instances` and `distractor_types`, and the last step's
`spl`, `soft_spl`, `path_length`, `distance_to_goal` and `shortest_path_length`.

`reset(seed=s)` is deterministic: the same seed gives the same scene, task and first observation;
`options={"scene": scene}` plays in a given `Scene`; `options={"split": "U+", "index": 3}` plays episode 3
of a frozen evaluation split (or `split=` at construction and `options={"index": 3}`; see `EnvConfig.split`):
the episode `luminous_sim.benchmark.entry_episode` defines, the same one `dataset build` and `luminous eval`
play; the reset's `info["episode_key"]` is the episode's content key (`benchmark.episode_key`);
`options={"cdf": path, "scene_seed": s}` (or `cdf=` at construction) generates the scene from a CDF file,
whose task section, if any, is the goal (see `luminous_sim.env.cdf_scenes`). The options are checked before
anything happens (`luminous_sim.env.reset_options`): an unknown key, options of two sources, or a value of
the wrong type is a one-line `LuminousError` naming the option and what was expected.

A world is built once per scene and reused while episodes stay in that scene (a repeated `options["scene"]`,
split entries sharing a layout): `World.reset_to_start` puts it back as built in about a millisecond instead
of a build's fraction of a second, with the same observations, rewards and infos to follow (see
`luminous_sim.env.worlds`). The reset's `info["redraws"]` counts the draws rejected before the episode: the
env keeps only episodes its expert solves (`verify_expert`, as ALFRED's generator keeps only tasks its
planner solves), so the population is "solvable by the expert", and redraws say how much was filtered.
"""

from __future__ import annotations

import string
from dataclasses import replace
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from luminous_sim.env.actions import ALFRED_ACTIONS, INTERACTIONS, NAVIGATION, STOP_NAMES, ActionTable, EmptySlot
from luminous_sim.env.cdf_scenes import cdf_episode, cdf_paths
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.episodes import (
    Episode,
    check_rooms,
    content_key,
    draw_episode,
    requested_entry,
    split_episode,
    trial_episode,
)
from luminous_sim.env.expert import Expert
from luminous_sim.env.goal_mask import goal_mask, goal_type
from luminous_sim.env.history import Sent
from luminous_sim.env.navscore import NavScore, nav_score
from luminous_sim.env.replay import episode_data, episode_from_data, history_data, replay
from luminous_sim.env.reset_options import reset_options
from luminous_sim.env.rewards import RewardConfig
from luminous_sim.env.shaping import RewardShaper
from luminous_sim.env.worlds import WorldPool
from luminous_sim.errors import FailureCode, LuminousError
from luminous_sim.vocab import ALL_TYPES, abilities
from luminous_sim.world import World

INSTRUCTION_CHARSET = string.ascii_letters + string.digits + " .,;:'!?-()\n"
MAX_INSTRUCTION = 1000
"""Characters of `instruction` kept (a directive is under 100; step instructions add about 60 a step)."""
MAX_HIGH_DESCS = 4000
"""Characters of `high_descs` kept (ALFRED's longest plans have about 25 steps of under 150 characters)."""
DEPTH_FAR = 20.0
"""The camera's far plane (metres): the largest depth."""
POSE_BOUND = 1000.0


class ResetNeeded(LuminousError, gymnasium.error.ResetNeeded):
    """`step()` (or an observation) asked for with no episode going: before the first `reset()`, or after the
    episode ended (terminated or truncated); call `reset()`. Both a `LuminousError` and gymnasium's
    `ResetNeeded`."""


def _type_index(object_type: str | None) -> int:
    """An object type as an observation: its index in `ALL_TYPES` plus one; 0 for none."""
    return ALL_TYPES.index(object_type) + 1 if object_type in ALL_TYPES else 0


def _interactable(object_type: str) -> bool:
    ab = abilities(object_type)
    return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable or ab.sliceable


def _clean_text(text: str, limit: int = MAX_INSTRUCTION) -> str:
    out = "".join(ch if ch in INSTRUCTION_CHARSET else " " for ch in text)[:limit]
    return out or "."


def _checked_seed(seed: Any) -> int | None:
    """`reset`'s seed: None or a whole number >= 0 (a numpy integer is taken as its value).

    Raises:
        LuminousError: anything else (a string, a float, a bool, a negative number), naming `seed`; checked
            before gymnasium sees it, which would raise its own `gymnasium.error.Error`.
    """
    if seed is None:
        return None
    if isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer)) or seed < 0:
        shown = repr(seed) if len(repr(seed)) <= 40 else repr(seed)[:37] + "..."
        raise LuminousError(f"reset seed: expected a whole number >= 0 or None, got {shown}")
    return int(seed)


class LuminousEnv(gymnasium.Env):
    """ALFRED's low-level actions, observations and limits in a generated room; see the module docstring.

    It wires its parts together: episodes (`episodes`, `cdf_scenes`), worlds (`WorldPool`), the expert
    (`Expert`), the reward (`RewardShaper`) and pickling by replay (`replay`).
    """

    metadata: dict[str, Any] = {"render_modes": ["rgb_array"], "render_fps": 6}  # noqa: RUF012  (as gymnasium.Env)

    def __init__(self, render_mode: str | None = None, **kwargs: Any):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise LuminousError(f"render_mode {render_mode!r}: expected one of {self.metadata['render_modes']}")
        self.render_mode = render_mode
        self.config = EnvConfig.from_kwargs(kwargs)
        check_rooms(self.config)
        self.rewards = RewardConfig.of(self.config.reward_mode, self.config.reward)
        c = self.config
        self.actions = ActionTable(c.width, c.height, c.grid, c.object_slots if c.targets == "objects" else 0)
        self.action_space = spaces.Discrete(self.actions.n)
        obs: dict[str, spaces.Space] = {
            "rgb": spaces.Box(0, 255, (c.height, c.width, 3), np.uint8),
            "instruction": spaces.Text(MAX_INSTRUCTION, min_length=1, charset=INSTRUCTION_CHARSET),
        }
        if c.high_descs:
            obs["high_descs"] = spaces.Text(MAX_HIGH_DESCS, min_length=1, charset=INSTRUCTION_CHARSET)
        if c.depth:
            obs["depth"] = spaces.Box(0.0, DEPTH_FAR, (c.height, c.width, 1), np.float32)
        if c.segmentation:
            obs["segmentation"] = spaces.Box(-1, np.iinfo(np.int32).max, (c.height, c.width), np.int32)
        if c.goal_mask:
            obs["goal_mask"] = spaces.Box(0, 255, (c.height, c.width, 1), np.uint8)
        if c.pose:
            obs["pose"] = spaces.Box(np.array([-POSE_BOUND, -POSE_BOUND, 0, -30], np.float32),
                                     np.array([POSE_BOUND, POSE_BOUND, 270, 60], np.float32), dtype=np.float32)
        if c.inventory:
            obs["inventory"] = spaces.Discrete(len(ALL_TYPES) + 1)
        if self.actions.slots:
            obs["objects"] = spaces.MultiDiscrete(np.full(self.actions.slots, len(ALL_TYPES) + 1, np.int64))
        self.observation_space = spaces.Dict(obs)
        self.world: World | None = None
        """The episode's world (None before the first reset and after `close`)."""
        self.worlds = WorldPool(self.config)
        """Worlds kept for reuse while episodes stay in one scene (`builds` and `reuses` count them)."""
        self.episode: Episode | None = None
        self.history: list[Sent] = []
        self.expert: Expert | None = None
        """The episode's expert (None before the first reset)."""
        self.shaper = RewardShaper(self.rewards, self.config.navigation_reward)
        """The episode's goal scores and reward."""
        self.navscore: NavScore | None = None
        """The episode's navigation figures (start distance, SPL) when its goal is scored so (`navscore`)."""
        self._slots: list[str] = []
        self._texts = (".", ".")
        """The episode's `instruction` and `high_descs` texts (made at reset)."""
        self._goal_type = ""
        """The type the `goal_mask` observation shows (`goal_mask.goal_type`)."""
        self._steps = 0
        self._failures = 0
        self._ended = False

    # ------------------------------------------------------------------ gymnasium API

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        """A new episode: a scene (generated, `options["scene"]`, a split's entry or a CDF's), a goal that fits
        it, the first view. The options are checked first (`reset_options`): a bad one is a `LuminousError`
        naming it, and nothing changes."""
        seed = _checked_seed(seed)
        checked = reset_options(options, self.config)
        super().reset(seed=seed)
        rng = np.random.default_rng(int(self.np_random.integers(2**63)))
        self._close_world()
        self.episode = None
        entry = requested_entry(self.config, checked, rng)
        paths = cdf_paths(self.config, checked)
        if entry is not None:
            self.episode, self.world = split_episode(self.config, entry, self.worlds)
        elif checked.trial:
            self.episode, self.world = trial_episode(self.config, checked.trial, self.worlds)
        elif paths:
            self.episode, self.world = cdf_episode(self.config, paths, rng, self.worlds, checked.scene_seed)
        else:
            self.episode, self.world = draw_episode(self.config, rng, self.worlds, scene=checked.scene)
        if not self.episode.key:
            self.episode = replace(self.episode, key=content_key(self.episode, self.world))
        self._start(self.episode, self.world)
        extra = self.navscore.at_start() if self.navscore is not None else {}
        return self._observation(), {**self._info(None, ""), "redraws": self.episode.redraws,
                                     "episode_key": self.episode.key, **extra}

    def _start(self, episode: Episode, world: World) -> None:
        self.history, self._steps, self._failures, self._ended = [], 0, 0, False
        self._texts = self._episode_texts()
        self._goal_type = goal_type(episode.goal)
        self.expert = Expert.for_episode(episode, self.worlds)
        self.shaper.start(episode.goal, world, episode.expert)
        self.navscore = nav_score(episode.goal, world)

    def step(self, action: Any):
        """One action (a discrete index or an ALFRED dict); see the module docstring.

        Raises:
            ResetNeeded: before the first `reset()`, or after the episode ended (the world is left as it is).
        """
        world = self._world()
        if self._ended:
            raise ResetNeeded("step() after the episode ended (terminated or truncated): call reset() first")
        self._steps += 1
        api, code, error = self._decode(action)
        stopped = api is not None and api["action"] in STOP_NAMES
        if api is not None and not stopped:
            result = world.step(api)
            self.history.append(Sent(action, api, result.success))
            code, error = result.code, result.error
        ok = code is None
        if not ok:
            self._failures += 1
        reward = self.shaper.step(world, api["action"] if api else None, ok, self._steps)
        terminated = self.shaper.success or stopped
        truncated = not terminated and (self._steps >= self.config.max_steps
                                        or self._failures >= self.config.max_failures)
        self._ended = terminated or truncated
        info = self._info(code, error)
        if self.navscore is not None and (terminated or truncated):
            info.update(self.navscore.at_end(world.agent, self.history, self.shaper.success))
        return self._observation(), reward, terminated, truncated, info

    def render(self) -> np.ndarray | None:
        """The agent's view (rgb_array), or None without a render mode."""
        if self.render_mode != "rgb_array" or self.world is None:
            return None
        return self.world.frame().rgb.copy()

    def top_down(self) -> np.ndarray:
        """A labelled top-down map of the room as it is now, with the reachable grid (an RGB array)."""
        return np.asarray(self._world("top_down()").view().top_down(grid=True).convert("RGB"))

    def close(self) -> None:
        self._close_world()
        self.worlds.clear()
        super().close()

    # ------------------------------------------------------------------ the expert and the action form

    def expert_action(self) -> int | dict[str, Any]:
        """The expert's next action in this env's action form: a discrete index when one names what the
        expert means (for an interaction, a grid point on its target, or its slot), else the ALFRED dict
        with the object id (the target covers no grid point, or has no slot); Stop when the expert has
        nothing left to do."""
        if self.expert is None:
            raise ResetNeeded("call reset() before expert_action()")
        api = self.expert.next_api(self.history)
        action = self.action_for(api)
        self.expert.suggested(len(self.history), action)
        return action

    def action_for(self, api: dict[str, Any] | None) -> int | dict[str, Any]:
        """An api action (object ids, as the oracle sends them) in this env's action form, for the current
        observation: a discrete index when one names it, else the api dict itself; Stop for None."""
        if api is None:
            return self.actions.index("Stop")
        name = api["action"]
        if name in NAVIGATION:
            return self.actions.index(name)
        target = api.get("receptacleObjectId") if name == "PutObject" else api.get("objectId")
        if self.actions.slots:
            slot = self._slots.index(target) if target in self._slots else None
            return self.actions.index(name, slot) if slot is not None else dict(api)
        mask = self._world().instance_masks().get(target) if name in INTERACTIONS and isinstance(target, str) \
            else None
        cell = self.actions.cell_on(mask) if mask is not None else None
        return self.actions.index(name, cell) if cell is not None else dict(api)

    @property
    def slots(self) -> tuple[str, ...]:
        """The object ids in the slots of the last observation (`objects` targets; empty otherwise)."""
        return tuple(self._slots)

    # ------------------------------------------------------------------ insides

    def _world(self, caller: str = "step()") -> World:
        """The episode's world; ResetNeeded before the first reset."""
        if self.world is None or self.episode is None:
            raise ResetNeeded(f"call reset() before {caller}")
        return self.world

    def _decode(self, action: Any) -> tuple[dict[str, Any] | None, FailureCode | None, str]:
        """The api action to send, or None with the code and message of an invalid one."""
        if isinstance(action, np.ndarray) and action.shape == () and action.dtype.kind in "iu":
            action = int(action)
        if isinstance(action, (int, np.integer)) and not isinstance(action, bool):
            if not 0 <= int(action) < self.actions.n:
                return None, FailureCode.INVALID_ARGUMENT, f"action {action} is outside 0..{self.actions.n - 1}"
            try:
                return self.actions.decode(int(action), self._slots), None, ""
            except EmptySlot as exc:
                return None, FailureCode.NO_TARGET, str(exc)
        if isinstance(action, dict) and isinstance(action.get("action"), str):
            name = action["action"]
            if name in STOP_NAMES or name in ALFRED_ACTIONS:
                return dict(action), None, ""
            return None, FailureCode.UNKNOWN_ACTION, (f"unknown action {name!r}; expected Stop or one of "
                                                      f"{', '.join(sorted(ALFRED_ACTIONS))}")
        return None, FailureCode.INVALID_ARGUMENT, (f"an action is an index in 0..{self.actions.n - 1} or a dict "
                                                    f"with an 'action' name, not {type(action).__name__}")

    def _observation(self) -> dict[str, Any]:
        world = self._world()
        frame = world.frame()
        c = self.config
        # a copy: the World keeps the frame, and a caller may write into what it is given
        obs: dict[str, Any] = {"rgb": np.array(frame.rgb[..., :3], dtype=np.uint8, order="C"),
                               "instruction": self._texts[0]}
        if c.high_descs:
            obs["high_descs"] = self._texts[1]
        if c.depth:
            depth = np.nan_to_num(frame.depth, nan=DEPTH_FAR, posinf=DEPTH_FAR, neginf=0.0)  # never NaN: in the space
            obs["depth"] = np.clip(depth, 0.0, DEPTH_FAR).astype(np.float32)[..., None]
        if c.segmentation:
            obs["segmentation"] = world.instance_ids().astype(np.int32)
        if c.goal_mask:
            obs["goal_mask"] = goal_mask(world, self._goal_type)
        if c.pose:
            p = world.agent
            obs["pose"] = np.array([p.x, p.y, p.rotation % 360, p.horizon], np.float32)
        state = world.view().state
        if c.inventory:
            obs["inventory"] = _type_index(state.objects[state.held].object_type if state.held else None)
        if self.actions.slots:
            self._slots = self._visible_slots(world)
            kinds = [_type_index(state.objects[o].object_type) for o in self._slots]
            obs["objects"] = np.array(kinds + [0] * (self.actions.slots - len(kinds)), np.int64)
        return obs

    def _visible_slots(self, world: World) -> list[str]:
        """Objects in view and within reach that an interaction applies to, the held one aside, most pixels
        first (ties by id), as many as there are slots."""
        state = world.view().state
        seen = [(-n, o) for o, n in world.visible_objects().items()
                if o in state.objects and o != state.held and _interactable(state.objects[o].object_type)]
        return [o for _, o in sorted(seen)[: self.actions.slots]]

    def _episode_texts(self) -> tuple[str, str]:
        """The episode's `instruction` (the goal directive, then with `step_instructions` the expert plan's step
        instructions) and `high_descs` (the step instructions, one per line): made once per episode."""
        assert self.episode is not None
        steps = self.episode.expert.steps if self.episode.expert is not None else ()
        text = self.episode.goal.instruction
        if self.config.step_instructions and steps:
            text = " ".join((text.rstrip(".") + ".", *steps))
        return _clean_text(text), _clean_text("\n".join(steps), MAX_HIGH_DESCS)

    def _info(self, code: FailureCode | None, error: str) -> dict[str, Any]:
        assert self.episode is not None
        goal = self.episode.goal
        scores = self.shaper.scores
        info: dict[str, Any] = {
            "success": self.shaper.success,
            "goal_conditions": (sum(scores.values()), sum(goal.weights().values())),
            "subgoal": goal.subgoal(scores),
            "task_type": goal.task_type,
            "failures": self._failures,
            "failure_code": None if code is None else code.value,
            "error": error,
        }
        if self.config.expert_in_info:
            info["expert_action"] = self.expert_action()
        return info

    def _close_world(self) -> None:
        """Give the world back to the pool (kept, restored, for another episode in its scene)."""
        if self.world is not None:
            self.worlds.put(self.world)
            self.world = None

    # ------------------------------------------------------------------ pickling (by replay: `env.replay`)

    def __getstate__(self) -> dict[str, Any]:
        """The config, the random state and the episode so far; the world is rebuilt and replayed on load."""
        return {
            "render_mode": self.render_mode, "kwargs": self.config.to_kwargs(),
            "np_random": self._np_random,
            "episode": None if self.episode is None else episode_data(self.episode),
            "history": history_data(self.history),
            "counters": (self._steps, self._failures, self.shaper.reached),
            "ended": self._ended,
        }

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__init__(state["render_mode"], **state["kwargs"])  # type: ignore[misc]
        self._np_random = state["np_random"]
        if state["episode"] is None:
            return
        episode = self.episode = episode_from_data(state["episode"])
        world = self.world = self.worlds.get(episode.scene, episode.dirty, episode.start)
        self._start(episode, world)
        self.history = replay(world, state["history"], self.shaper)
        self._steps, self._failures, reached = state["counters"]
        self.shaper.resume(world, reached)
        self._ended = bool(state.get("ended", False))
        self._observation()  # the object slots the agent saw last
