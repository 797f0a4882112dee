"""Luminous-Sim: interactive indoor scenes and ALFRED-style household tasks on PyBullet."""

from luminous_sim.env.registration import register_envs as _register_envs
from luminous_sim.errors import LuminousError

__all__ = ["LuminousError", "__version__"]
__version__ = "0.2.0"

_register_envs()  # the Gymnasium ids of envs/*.toml, by string entry point: imports neither world/ nor pybullet
