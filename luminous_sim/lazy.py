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
