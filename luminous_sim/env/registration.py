"""Gymnasium ids from the declarative specs in `envs/*.toml` (one file per family of ids).

`envs/` is the one copy of the specs. Where they are read from: in an installed wheel, the package data
`luminous_sim/env/specs/`, which the build copies from `envs/` (setup.py's build hook); in a source checkout
or an editable install, the repository's `envs/` beside the package (the documented place to add or change
an environment, a data-only change). A spec file looks like::

    [family]
    entry_point = "luminous_sim.env.alfred_env:LuminousEnv"
    [family.kwargs]          # defaults for every id of the file
    width = 300
    [[env]]
    id = "Luminous-ALFRED-PickHeat-v1"
    description = "..."
    kwargs.task_types = ["pick_heat_then_place_in_recep"]
    eval = { first_seed = 1000000, episodes = 200 }   # optional: the id's held-out evaluation seeds

Registration is lazy: ids map to a string entry point, so registering imports neither the simulator
nor pybullet; the keyword arguments are plain JSON data (`EnvConfig` fields, checked here).
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from importlib import resources
from importlib.resources.abc import Traversable
from pathlib import Path
from typing import Any

from luminous_sim.env.config import EnvConfig
from luminous_sim.errors import LuminousError

REPO_SPECS = Path(__file__).resolve().parents[2] / "envs"
"""The specs, in a source checkout or an editable install (the one copy)."""
PACKAGE_SPECS = "specs"
"""Where a wheel holds them, inside this package (copied from `envs/` at build time, absent from the source)."""
_FAMILY_KEYS = {"entry_point", "kwargs", "eval"}
_ENV_KEYS = {"id", "description", "kwargs", "entry_point", "eval"}
_EVAL_KEYS = {"first_seed", "episodes"}


@dataclass(frozen=True)
class EnvEntry:
    """One registered id: where it comes from, its entry point and its keyword arguments."""

    id: str
    entry_point: str
    kwargs: dict[str, Any] = field(default_factory=dict)
    description: str = ""
    source: str = ""
    eval_seeds: tuple[int, ...] = ()
    """The held-out evaluation episodes, as `reset(seed=...)` seeds (the spec's `eval` table; empty if none):
    `first_seed`, `first_seed + 1`, ... (`episodes` of them). Train on other seeds."""


def spec_folder() -> Traversable:
    """The folder the specs are read from: the wheel's package data if installed so, else the repository's `envs/`.

    Raises:
        LuminousError: neither exists (a wheel built without the build hook, or a checkout without `envs/`).
    """
    shipped = resources.files(__package__) / PACKAGE_SPECS
    if shipped.is_dir():
        return shipped
    if REPO_SPECS.is_dir():
        return REPO_SPECS
    raise LuminousError(f"no environment specs: neither the package data {shipped} nor {REPO_SPECS} exists "
                        "(build the wheel with the project's setup.py, which copies envs/*.toml into it)")


def spec_files() -> list[Traversable]:
    """The spec files, sorted by name (see `spec_folder`)."""
    return sorted((f for f in spec_folder().iterdir() if f.name.endswith(".toml")), key=lambda f: f.name)


def read_spec(text: str, source: str) -> list[EnvEntry]:
    """The entries of one spec file's text; errors name the file and the key.

    Raises:
        LuminousError: not TOML, an unknown key, a missing id or entry point, or kwargs that are not a
            valid `EnvConfig`.
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise LuminousError(f"{source}: not valid TOML: {exc}") from None
    unknown = sorted(set(data) - {"family", "env"})
    if unknown:
        raise LuminousError(f"{source}: unknown top-level key(s) {', '.join(unknown)}; expected family, env")
    family = data.get("family", {})
    if sorted(set(family) - _FAMILY_KEYS):
        raise LuminousError(f"{source}: family: unknown key(s) {', '.join(sorted(set(family) - _FAMILY_KEYS))}")
    entries = []
    for i, env in enumerate(data.get("env", [])):
        where = f"{source}: env[{i}]"
        if sorted(set(env) - _ENV_KEYS):
            raise LuminousError(f"{where}: unknown key(s) {', '.join(sorted(set(env) - _ENV_KEYS))}; expected "
                                f"{', '.join(sorted(_ENV_KEYS))}")
        if not isinstance(env.get("id"), str):
            raise LuminousError(f"{where}: id: expected a string such as 'Luminous-Name-v0'")
        entry_point = env.get("entry_point", family.get("entry_point"))
        if not isinstance(entry_point, str) or ":" not in entry_point:
            raise LuminousError(f"{where} ({env['id']}): entry_point: expected 'module:Class'")
        kwargs = {**family.get("kwargs", {}), **env.get("kwargs", {})}
        try:
            EnvConfig.from_kwargs(kwargs)
        except LuminousError as exc:
            raise LuminousError(f"{where} ({env['id']}): {exc}") from None
        seeds = _eval_seeds(env.get("eval", family.get("eval")), f"{where} ({env['id']}): eval")
        entries.append(EnvEntry(env["id"], entry_point, kwargs, env.get("description", ""), source, seeds))
    return entries


def _eval_seeds(table: Any, where: str) -> tuple[int, ...]:
    """The seeds of an `eval` table (`first_seed`, `episodes`); () for none."""
    if table is None:
        return ()
    if not isinstance(table, dict) or set(table) != _EVAL_KEYS or not all(
            isinstance(table[k], int) and not isinstance(table[k], bool) and table[k] >= 0 for k in _EVAL_KEYS):
        raise LuminousError(f"{where}: expected a table {{ first_seed = <int >= 0>, episodes = <int >= 0> }}, "
                            f"got {table!r}")
    return tuple(range(table["first_seed"], table["first_seed"] + table["episodes"]))


def eval_seeds(env_id: str) -> tuple[int, ...]:
    """The held-out evaluation seeds a spec fixes for the id (`reset(seed=s)` for each); () if it fixes none.

    Raises:
        LuminousError: no spec defines the id.
    """
    for e in load_entries():
        if e.id == env_id:
            return e.eval_seeds
    raise LuminousError(f"no environment spec defines {env_id!r}")


def load_entries() -> list[EnvEntry]:
    """Every spec's entries, in file order; an id defined twice is an error."""
    entries: list[EnvEntry] = []
    for f in spec_files():
        entries += read_spec(f.read_text(encoding="utf-8"), f.name)
    seen: dict[str, str] = {}
    for e in entries:
        if e.id in seen:
            raise LuminousError(f"{e.source}: id {e.id} is already defined in {seen[e.id]}")
        seen[e.id] = e.source
    return entries


def register_envs() -> list[str]:
    """Register every spec's id with gymnasium (ids already registered are left alone); the ids."""
    import gymnasium

    ids = []
    for e in load_entries():
        if e.id not in gymnasium.registry:
            gymnasium.register(e.id, entry_point=e.entry_point, kwargs=e.kwargs)
        ids.append(e.id)
    return ids
