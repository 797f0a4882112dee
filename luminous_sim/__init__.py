"""Luminous-Sim: interactive indoor scenes and ALFRED-style household tasks on PyBullet."""

from luminous_sim.errors import LuminousError

__all__ = ["LuminousError", "__version__"]
__version__ = "0.1.0"
