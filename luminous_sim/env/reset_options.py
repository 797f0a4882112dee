"""`reset(options=...)`, checked: the options a reset takes, read into a typed `ResetOptions` before any work
starts, or refused with a one-line `LuminousError` naming the option and what was expected.

- `scene`: a `luminous_sim.scene.Scene`, checked as a scene file is (`scene.check_scene`: finite poses within
  bounds, unique ids, parents present, the object-count limit); the episode is played in it (only the goal is
  drawn).
- `split`, `index`: a frozen split's name (`S+`, `U+`, `U+test`) and a whole number below its size; entry
  `index` of the split (`index` alone: of the env's `split`; `split` alone: an entry drawn over the split's
  entries of the env's task types).
- `trial`: a built trial's folder (`traj_data.json` and the sidecar `luminous.json` of `luminous dataset
  build`); the episode restored from its files (`benchmark.read_trial`), its annotation 0 the instructions.
- `cdf`, `scene_seed`: a CDF file path, or a list of at most `MAX_CDF_FILES`, and a whole number
  0..2**63-1; a scene generated from a CDF (`scene_seed` alone: from the env's `cdf`).

The sources exclude each other: `scene`; `split`/`index`; `trial`; `cdf`/`scene_seed`. An option given as None
counts as not given. A source named in the options replaces the env's own (`EnvConfig.split`, `.cdf`) for
that reset.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.env.config import MAX_CDF_FILES, EnvConfig, short_repr
from luminous_sim.errors import LuminousError
from luminous_sim.scene import Scene, check_scene

if TYPE_CHECKING:
    from luminous_sim.benchmark import TrialEpisode

RESET_OPTIONS: tuple[str, ...] = ("scene", "split", "index", "trial", "cdf", "scene_seed")
"""The keys `reset(options=...)` knows."""
SOURCES: tuple[tuple[str, ...], ...] = (("scene",), ("split", "index"), ("trial",), ("cdf", "scene_seed"))
"""Groups of options that name where the episode comes from; options of two groups exclude each other."""
SEED_LIMIT = 2**63
"""`index` and `scene_seed` lie in 0..SEED_LIMIT - 1 (what a `numpy.random.SeedSequence` of an int64 takes)."""


@dataclass(frozen=True)
class ResetOptions:
    """A reset's options, checked (the defaults: none given).

    Attributes:
        scene: play in this scene.
        split: play an entry of this split ("" for none given).
        index: the entry of `split` (else of the env's split) to play; None to draw one.
        trial: the episode of a built trial folder, read from its files (None for none given).
        cdf: generate the scene from one of these CDF files (() for none given).
        scene_seed: the seed to generate the CDF's scene with; None to draw one.
    """

    scene: Scene | None = None
    split: str = ""
    index: int | None = None
    cdf: tuple[str, ...] = ()
    scene_seed: int | None = None
    trial: TrialEpisode | None = None

    @property
    def source(self) -> str:
        """Where the episode comes from: `scene`, `split`, `cdf`, or "" (the env's own source)."""
        if self.scene is not None:
            return "scene"
        if self.split or self.index is not None:
            return "split"
        if self.trial is not None:
            return "trial"
        if self.cdf or self.scene_seed is not None:
            return "cdf"
        return ""


def reset_options(options: Any, config: EnvConfig) -> ResetOptions:
    """The options of a reset of an env with this config, checked.

    Raises:
        LuminousError: not a dict; an unknown key (the message lists the known ones); options of two sources
            (`SOURCES`); `index` with no split to index, `scene_seed` with no CDF to seed; a value of the wrong
            type or out of range (the message names the option and what was expected); a CDF path that names
            no file.
    """
    if options is None:
        return ResetOptions()
    if not isinstance(options, Mapping):
        raise LuminousError(f"reset options: expected a dict with some of {', '.join(RESET_OPTIONS)}, got "
                            f"{type(options).__name__}")
    unknown = [k for k in options if k not in RESET_OPTIONS]
    if unknown:
        raise LuminousError(f"reset options: unknown key(s) {', '.join(short_repr(k) for k in unknown[:5])}; expected "
                            f"some of {', '.join(RESET_OPTIONS)}")
    given = {k: v for k, v in options.items() if v is not None}
    groups = [[k for k in group if k in given] for group in SOURCES]
    named = [g for g in groups if g]
    if len(named) > 1:
        raise LuminousError(f"reset options: {' and '.join(repr(g[0]) for g in named)} exclude each other; give "
                            "one of 'scene', 'split'/'index', 'trial' or 'cdf'/'scene_seed'")
    scene = given.get("scene")
    if scene is not None and not isinstance(scene, Scene):
        raise LuminousError(f"reset options scene: expected a luminous_sim.scene.Scene, got {type(scene).__name__}")
    if scene is not None:  # by the rules a scene file is read by: a copied Scene was never validated
        check_scene(scene, "reset options scene")
    split = _split(given["split"]) if "split" in given else ""
    index = _whole("index", given["index"]) if "index" in given else None
    if index is not None and not (split or config.split):
        raise LuminousError("reset options index: names an episode of a split; give 'split' too (or make the env "
                            "with split=...)")
    if index is not None:
        from luminous_sim.benchmark import benchmark_size

        size = benchmark_size(split or config.split)
        if index >= size:
            raise LuminousError(f"reset options index: {index}; split {split or config.split} holds episodes "
                                f"0..{size - 1}")
    trial = _trial(given["trial"]) if "trial" in given else None
    cdf = _cdf(given["cdf"]) if "cdf" in given else ()
    seed = _whole("scene_seed", given["scene_seed"]) if "scene_seed" in given else None
    if seed is not None and not (cdf or config.cdf):
        raise LuminousError("reset options scene_seed: seeds the scene of a CDF; give 'cdf' too (or make the env "
                            "with cdf=...)")
    return ResetOptions(scene, split, index, cdf, seed, trial)


def _trial(value: Any) -> TrialEpisode:
    """The trial a `trial` option names, read (so that a malformed one is refused before the reset starts)."""
    from luminous_sim.benchmark import TrialError, read_trial

    if not isinstance(value, (str, os.PathLike)):
        raise LuminousError(f"reset options trial: expected a trial folder's path, got {short_repr(value)}")
    path = Path(value)
    if not (path / "traj_data.json").is_file():
        raise LuminousError(f"reset options trial: {path} holds no traj_data.json; expected a built trial's folder")
    try:
        return read_trial(path)
    except TrialError as exc:
        raise LuminousError(f"reset options trial: {exc}") from None


def _split(value: Any) -> str:
    from luminous_sim.splits import PLUS_SPLITS

    if not isinstance(value, str) or value not in PLUS_SPLITS:
        raise LuminousError(f"reset options split: expected one of {', '.join(PLUS_SPLITS)}, got {short_repr(value)}")
    return value


def _whole(name: str, value: Any) -> int:
    if isinstance(value, np.ndarray) and value.shape == ():
        value = value[()]
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 0 <= int(value) < SEED_LIMIT:
        raise LuminousError(f"reset options {name}: expected a whole number in 0..2**63-1, got {short_repr(value)}")
    return int(value)


def _cdf(value: Any) -> tuple[str, ...]:
    paths = [value] if isinstance(value, (str, os.PathLike)) else value
    if not isinstance(paths, (list, tuple)) or not paths or not all(isinstance(p, (str, os.PathLike)) for p in paths):
        raise LuminousError(f"reset options cdf: expected a CDF file path or a non-empty list of them, got "
                            f"{short_repr(value)}")
    if len(paths) > MAX_CDF_FILES:
        raise LuminousError(f"reset options cdf: expected at most {MAX_CDF_FILES} files, got {len(paths)}")
    out = tuple(os.fspath(p) for p in paths)
    if not all(isinstance(p, str) for p in out):
        raise LuminousError(f"reset options cdf: expected text paths, got {short_repr(value)}")
    for p in out:
        if not Path(p).is_file():
            raise LuminousError(f"reset options cdf: {short_repr(p)}: no such CDF file")
    return out
