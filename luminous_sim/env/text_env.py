"""`Luminous-Text-v0`: a frozen split's episodes as text games for language-model agents (`text.TextGame`:
ALFWorld's observations, command grammar and step limit; all seven task types and sliced objects).

`reset(options={"split": "U+", "index": 7})` plays entry 7 of U+, the same episode (`info["episode_key"]`) the
embodied env plays for those options; `split` alone, or no options, draws an entry of the env's split over its
task types. The observation is text: the welcome, the room and the task after a reset, each command's
feedback after a step; `info["admissible_commands"]` lists the commands that do something, `info["won"]`
whether the task is done (its goal conditions, as the embodied env judges them). Reward 1 on the step that
wins, else 0; an episode ends when won and is truncated after `max_steps` commands (ALFWorld's 50).
The state is built without physics (`states.scene_state`); the env keeps the last `CACHED` entries' scenes,
so a second reset of an entry takes milliseconds. Figures: docs/benchmarks.md ("The native text env")."""

from __future__ import annotations

import string
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from luminous_sim.env.config import EnvConfig
from luminous_sim.env.episodes import requested_entry
from luminous_sim.env.reset_options import reset_options
from luminous_sim.errors import LuminousError
from luminous_sim.states import scene_state
from luminous_sim.text import TextGame
from luminous_sim.vocab import ALFRED_TASK_TYPES

MAX_STEPS = 50
"""ALFWorld's step limit per episode (its config's `max_nb_steps_per_episode`)."""
MAX_TEXT = 8192
"""The longest observation or command (characters)."""
CACHED = 64
"""Entries whose scene and starting state an env keeps (the oldest is dropped first): a second reset of one
takes milliseconds."""


class TextEnv(gymnasium.Env):
    """A frozen split's episodes as text games; see the module docstring."""

    metadata = {"render_modes": ["ansi"]}  # noqa: RUF012 (gymnasium.Env declares it so)

    def __init__(self, split: str = "S+", task_types: list[str] | tuple[str, ...] = ALFRED_TASK_TYPES,
                 max_steps: int = MAX_STEPS, render_mode: str | None = None):
        unknown = sorted(set(task_types) - set(ALFRED_TASK_TYPES))
        if unknown:
            raise LuminousError(f"text env task_types: {', '.join(unknown)} is none of ALFRED's seven types")
        if render_mode not in (None, "ansi"):
            raise LuminousError(f"text env render_mode: {render_mode!r}; expected None or 'ansi'")
        self.config = EnvConfig.from_kwargs({"split": split, "task_types": list(task_types), "max_steps": max_steps})
        self.render_mode = render_mode
        self.observation_space = spaces.Text(MAX_TEXT, charset=string.printable)
        self.action_space = spaces.Text(MAX_TEXT, charset=string.printable)
        self.game: TextGame | None = None
        self.episode: Any = None
        self._steps = 0
        self._last = ""
        self._made: dict[tuple[str, int], tuple[Any, Any]] = {}

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None):
        """A new episode of the env's split (or the one `options` names); the welcome and the task."""
        from luminous_sim.episodes import entry_spec
        from luminous_sim.tasks import alfred_description, goal_conditions

        checked = reset_options(options, self.config)
        if checked.source not in ("", "split"):
            raise LuminousError(f"text env reset options: {checked.source!r} is not a source of text episodes; "
                                "give 'split' and/or 'index'")
        super().reset(seed=seed)
        entry = requested_entry(self.config, checked, self.np_random)
        assert entry is not None, "the text env always has a split"
        key = (entry.split, entry.index)
        if key not in self._made:
            spec = entry_spec(entry)
            state = scene_state(spec.scene)
            for oid in spec.dirty:
                state = state.with_object(oid, isDirty=True)
            if len(self._made) >= CACHED:
                self._made.pop(next(iter(self._made)))
            self._made[key] = (spec, state)
        spec, state = self._made[key]
        task = spec.task
        wording = np.random.default_rng(np.random.SeedSequence([entry.task_seed, 44]))

        def met(now: Any, visible: set[str]) -> bool:
            done, total = goal_conditions(task, now, visible)
            return done == total

        self.game = TextGame(state, alfred_description(task, wording), met)
        self.episode, self._steps = spec, 0
        self._last = self.game.intro()
        return self._last, self._info(entry)

    def step(self, action: str):
        """One command; its feedback."""
        if self.game is None or self.game.won or self._steps >= self.config.max_steps:
            raise LuminousError("text env: call reset() first (the episode has ended or not begun)")
        if not isinstance(action, str) or len(action) > MAX_TEXT:
            raise LuminousError(f"text env action: expected a command of at most {MAX_TEXT} characters such as "
                                f"'go to countertop 1', got {type(action).__name__}")
        was = self.game.won
        self._last = self.game.step(action)
        self._steps += 1
        won = self.game.won
        return self._last, float(won and not was), won, self._steps >= self.config.max_steps and not won, self._info()

    def _info(self, entry: Any = None) -> dict[str, Any]:
        assert self.game is not None
        info: dict[str, Any] = {"admissible_commands": self.game.admissible(), "won": self.game.won,
                                "episode_key": self.episode.key, "task_type": self.episode.task.task_type,
                                "goal": self.game.goal_text}
        if entry is not None:
            info.update(split=entry.split, index=entry.index)
        return info

    def render(self) -> str | None:
        return self._last if self.render_mode == "ansi" else None
