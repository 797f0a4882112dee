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
the episode `luminous_sim.episodes.entry_spec` defines, the same one `dataset build` and `luminous eval`
play; the reset's `info["episode_key"]` is the episode's content key (`benchmark.episode_key`);
`options={"cdf": path, "scene_seed": s}` (or `cdf=` at construction) generates the scene from a CDF file,
whose task section, if any, is the goal (see `luminous_sim.episodes.cdf`). The options are checked before
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

from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from luminous_sim.env.actions import STOP_NAMES, ActionTable
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.episodes import check_rooms
from luminous_sim.env.expert import Expert
from luminous_sim.env.goal_mask import goal_type
from luminous_sim.env.history import Sent
from luminous_sim.env.measures import Failures, Measure, NavigationScore, Step, measures_for
from luminous_sim.env.navscore import NavScore
from luminous_sim.env.replay import episode_data, episode_from_data, history_data, replay
from luminous_sim.env.reset_options import reset_options
from luminous_sim.env.sensors import MAX_HIGH_DESCS, Reading, Sensor, clean_text, sensors_for
from luminous_sim.env.shaping import RewardShaper
from luminous_sim.env.sources import draw_episode
from luminous_sim.env.worlds import WorldPool
from luminous_sim.episodes import EpisodeSpec, keyed
from luminous_sim.errors import LuminousError
from luminous_sim.world import World


class ResetNeeded(LuminousError, gymnasium.error.ResetNeeded):
    """`step()` (or an observation) asked for with no episode going: before the first `reset()`, or after the
    episode ended (terminated or truncated); call `reset()`. Both a `LuminousError` and gymnasium's
    `ResetNeeded`."""


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

    It wires its parts together: episodes from the first source that applies (`env.sources`, drawing from
    `luminous_sim.episodes`), worlds (`WorldPool`), observations from sensors (`env.sensors`), `info` from
    measures (`env.measures`), the expert (`Expert`), the reward (`RewardShaper`) and pickling by replay
    (`replay`).
    """

    metadata: dict[str, Any] = {"render_modes": ["rgb_array"], "render_fps": 6}  # noqa: RUF012  (as gymnasium.Env)

    def __init__(self, render_mode: str | None = None, **kwargs: Any):
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise LuminousError(f"render_mode {render_mode!r}: expected one of {self.metadata['render_modes']}")
        self.render_mode = render_mode
        self.config = EnvConfig.from_kwargs(kwargs)
        check_rooms(self.config)
        self.rewards = self.config.rewards.config()
        c = self.config.actions
        self.actions = ActionTable(self.config.width, self.config.height, c.grid,
                                   c.object_slots if c.targets == "objects" else 0)
        self.action_space = spaces.Discrete(self.actions.n)
        self.sensors: list[Sensor] = sensors_for(self.config, self.actions)
        """The observations, one sensor each (`env.sensors`)."""
        self.observation_space = spaces.Dict({s.key: s.space() for s in self.sensors})
        self.measures: list[Measure] = measures_for(self)
        """What `info` reports, one measure each (`env.measures`)."""
        self._failures = next(m for m in self.measures if isinstance(m, Failures))
        """The failure count, which cuts an episode off at `max_failures`."""
        self.world: World | None = None
        """The episode's world (None before the first reset and after `close`)."""
        self.worlds = WorldPool(self.config)
        """Worlds kept for reuse while episodes stay in one scene (`builds` and `reuses` count them)."""
        self.episode: EpisodeSpec | None = None
        self.history: list[Sent] = []
        self.expert: Expert | None = None
        """The episode's expert (None before the first reset)."""
        self.shaper = RewardShaper(self.rewards, self.config.navigation_reward)
        """The episode's goal scores and reward."""
        self._slots: list[str] = []
        self._texts = (".", ".")
        """The episode's `instruction` and `high_descs` texts (made at reset)."""
        self._goal_type = ""
        """The type the `goal_mask` observation shows (`goal_mask.goal_type`)."""
        self._steps = 0
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
        self.episode, self.world = draw_episode(self.config, self.worlds, checked, rng)
        self.episode = keyed(self.episode, self.world.agent)
        self._start(self.episode, self.world)
        return self._observation(), self._info(None)

    def _start(self, episode: EpisodeSpec, world: World) -> None:
        self.history, self._steps, self._ended = [], 0, False
        self._texts = self._episode_texts()
        self._goal_type = goal_type(episode.goal)
        self.expert = Expert.for_episode(episode, self.worlds)
        self.shaper.start(episode.goal, world, episode.expert)
        for measure in self.measures:
            measure.reset(self)

    def step(self, action: Any):
        """One action (a discrete index or an ALFRED dict); see the module docstring.

        Raises:
            ResetNeeded: before the first `reset()`, or after the episode ended (the world is left as it is).
        """
        world = self._world()
        if self._ended:
            raise ResetNeeded("step() after the episode ended (terminated or truncated): call reset() first")
        self._steps += 1
        api, code, error = self.actions.to_api(action, self._slots)
        stopped = api is not None and api["action"] in STOP_NAMES
        if api is not None and not stopped:
            result = world.step(api)
            self.history.append(Sent(action, api, result.success))
            code, error = result.code, result.error
        for measure in self.measures:
            measure.update(self, Step(code, error))
        reward = self.shaper.step(world, api["action"] if api else None, code is None, self._steps)
        terminated = self.shaper.success or stopped
        truncated = not terminated and (self._steps >= self.config.max_steps
                                        or self.failures >= self.config.max_failures)
        self._ended = terminated or truncated
        return self._observation(), reward, terminated, truncated, self._info(Step(code, error, terminated, truncated))

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
        observation: a discrete index when one names it, else the api dict itself; Stop for None
        (`ActionTable.from_api`)."""
        return self.actions.from_api(api, self._slots, lambda: self._world().instance_masks())

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

    def _observation(self) -> dict[str, Any]:
        world = self._world()
        reading = Reading(world, world.frame(), *self._texts, self._goal_type)
        obs = {sensor.key: sensor.read(reading) for sensor in self.sensors}
        if self.actions.slots:
            self._slots = reading.slots
        return obs

    def _episode_texts(self) -> tuple[str, str]:
        """The episode's `instruction` (the goal directive, then with `step_instructions` the expert plan's step
        instructions) and `high_descs` (the step instructions, one per line): made once per episode."""
        assert self.episode is not None
        steps = self.episode.expert.steps if self.episode.expert is not None else ()
        text = self.episode.goal.instruction
        if self.config.step_instructions and steps:
            text = " ".join((text.rstrip(".") + ".", *steps))
        return clean_text(text), clean_text("\n".join(steps), MAX_HIGH_DESCS)

    def _info(self, step: Step | None) -> dict[str, Any]:
        """What the measures report (`step` None at reset)."""
        info: dict[str, Any] = {}
        for measure in self.measures:
            info.update(measure.info(self, step))
        return info

    @property
    def failures(self) -> int:
        """The episode's failed actions so far."""
        return self._failures.count

    @property
    def navscore(self) -> NavScore | None:
        """The episode's navigation figures (start distance, SPL) when its goal is scored so (`navscore`)."""
        return next((m.score for m in self.measures if isinstance(m, NavigationScore)), None)

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
            "counters": (self._steps, self.failures, self.shaper.reached),
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
        self._steps, failures, reached = state["counters"]
        self._failures.count = failures
        self.shaper.resume(world, reached)
        self._ended = bool(state.get("ended", False))
        self._observation()  # the object slots the agent saw last
