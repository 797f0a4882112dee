"""Public names of a package loaded on first use (PEP 562), so that importing the package stays cheap
(no pybullet for `luminous_sim.world.masks`, no simulator for `import luminous_sim`)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from importlib import import_module
from typing import Any


def lazy_getattr(package: str, where: Mapping[str, str]) -> Callable[[str], Any]:
    """A module `__getattr__` for `package`: `where` maps each public name to the module defining it,
    absolute (`luminous_sim.errors`) or relative to the package (`oracle`)."""

    def __getattr__(name: str) -> Any:
        if name in where:
            module = where[name]
            return getattr(import_module(module if module.startswith("luminous_sim.") else f"{package}.{module}"),
                           name)
        raise AttributeError(f"module {package!r} has no attribute {name!r}")

    return __getattr__


def moved_getattr(old: str, where: Mapping[str, str], until: str) -> Callable[[str], Any]:
    """A module `__getattr__` for a path whose public names moved: `where` maps each name to its new module
    (absolute); the name is returned from there with a `DeprecationWarning` naming the new path, which is the
    only one after release `until`."""
    import warnings

    def __getattr__(name: str) -> Any:
        if name in where:
            warnings.warn(f"{old}.{name} moved to {where[name]}.{name}; the old path goes in release {until}",
                          DeprecationWarning, stacklevel=2)
            return getattr(import_module(where[name]), name)
        raise AttributeError(f"module {old!r} has no attribute {name!r}")

    return __getattr__
