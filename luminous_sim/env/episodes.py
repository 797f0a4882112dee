"""The env's link to `luminous_sim.episodes`: the `Drawing` an `EnvConfig` asks for (its task types, each
kind configured with the task options, the rooms the config allows, the attempts and the expert's proof),
the room check a config gets at construction, and the split entry a reset asks for. Episodes themselves (the
spec, ALFRED's set-up, the expert's proof and every source) live in `luminous_sim.episodes`."""

from __future__ import annotations

import numpy as np

from luminous_sim.benchmark import BenchmarkEntry, benchmark_entries, benchmark_entry
from luminous_sim.env.config import EnvConfig
from luminous_sim.env.kinds import set_up, task_kind
from luminous_sim.env.reset_options import ResetOptions
from luminous_sim.episodes import Drawing, set_initial
from luminous_sim.errors import LuminousError
from luminous_sim.lazy import moved_getattr
from luminous_sim.world import World


def set_up_world(world: World, task_type: str) -> tuple[str, ...]:
    """Set a world up for an episode of the kind (`TaskKind.set_up`: e.g. for cleaning, everything dirtyable
    dirty; nothing for a type no kind registers, a CDF's own task); the objects it made dirty."""
    dirty = set_up(world, task_type)
    set_initial(world, dirty)
    return dirty


def drawing(config: EnvConfig) -> Drawing:
    """How the env draws its episodes (`episodes.Drawing`)."""
    options = config.task_options
    return Drawing(tuple(config.task_types), lambda t: task_kind(t).configured(options), set_up_world,
                   lambda t: room_types(config, t), config.scene_attempts, config.verify_expert)


def room_types(config: EnvConfig, task_type: str) -> list[str]:
    """The room types an episode of the kind may be generated in (`TaskKind.rooms`, the config's choice).

    Raises:
        LuminousError: the config's room types leave none (`check_rooms` refuses such a config up front).
    """
    allowed = list(task_kind(task_type).rooms())
    chosen = [r for r in allowed if not config.room_types or r in config.room_types]
    if not chosen:
        raise LuminousError(_unfit([task_type], config.room_types))
    return chosen


def check_rooms(config: EnvConfig) -> None:
    """Refuse room types that cannot go with the task types (each kind's `rooms()`, ALFRED's table for its
    types): a task type played in none of them, or a room type no task type is played in. Nothing is
    checked without room types (each task type then goes to every room it allows).

    Raises:
        LuminousError: one line naming the task types that do not fit, the room types and the rooms each
            allows (or the room types no task type uses).
    """
    if not config.room_types:
        return
    chosen = set(config.room_types)
    types = list(dict.fromkeys(config.task_types))
    unfit = [t for t in types if not chosen.intersection(task_kind(t).rooms())]
    if unfit:
        raise LuminousError(_unfit(unfit, config.room_types))
    used = {r for t in types for r in task_kind(t).rooms()}
    idle = [r for r in dict.fromkeys(config.room_types) if r not in used]
    if idle:
        raise LuminousError(f"env config room_types: no task of {', '.join(types)} is played in "
                            f"{', '.join(idle)}; drop {'it' if len(idle) == 1 else 'them'}")


def _unfit(task_types: list[str], rooms: tuple[str, ...]) -> str:
    """The message for task types played in none of the config's room types."""
    where = "; ".join(f"{t} is played only in {', '.join(task_kind(t).rooms())}" for t in task_types)
    return (f"env config room_types: {', '.join(rooms)} allow{'s' if len(rooms) == 1 else ''} no "
            f"{' or '.join(task_types)} task ({where}); add one of those room types or drop the task type from "
            "task_types")


def requested_entry(config: EnvConfig, options: ResetOptions, rng: np.random.Generator) -> BenchmarkEntry | None:
    """The split entry a reset asks for (`options.split`, else `config.split`; `options.index`, else one drawn
    from `rng` over the split's entries of the env's task types), or None for an episode from elsewhere (a
    scene or a CDF the options name, the env's CDFs, or generated on the fly).

    Raises:
        LuminousError: an entry of a task type the env does not play, or a split with none of them.
    """
    if options.source not in ("", "split"):
        return None
    name = options.split or config.split
    if not name:
        return None
    index = options.index
    if index is None:
        mine = [e.index for e in benchmark_entries(name) if e.task_type in config.task_types]
        if not mine:
            raise LuminousError(f"split {name} holds no episode of {', '.join(config.task_types)}")
        index = mine[int(rng.integers(len(mine)))]
    entry = benchmark_entry(name, index)
    if entry.task_type not in config.task_types:
        raise LuminousError(f"{name} episode {index} is a {entry.task_type} task; this env plays only "
                            f"{', '.join(config.task_types)}")
    return entry


def cdf_paths(config: EnvConfig, options: ResetOptions) -> tuple[str, ...]:
    """The CDF files a reset draws from: `options.cdf` (checked by `reset_options`), else `config.cdf` unless
    the options name another source (a scene or a split)."""
    if options.cdf:
        return options.cdf
    return config.cdf if options.source == "" else ()


__all__ = ["cdf_paths", "check_rooms", "drawing", "requested_entry", "room_types",
           "set_up_world"]

__getattr__ = moved_getattr(__name__, dict.fromkeys(("UNAVAILABLE_CAUSES", "EpisodeUnavailable"),
                                                   "luminous_sim.episodes"), "0.3.0")
